/**
 * Playground downloads: POST the system on the page (#playground-system) with the values the
 * simulation controls now hold to /api/export, and save the answer as a file.
 */
import { fetchRetrying } from "./api.js";
import { readRequest } from "./controls.js";

const status = document.getElementById("export-status");

function request(format) {
  const system = JSON.parse(document.getElementById("playground-system").textContent || "{}");
  const form = document.getElementById("controls");
  const wanted = form ? readRequest(form) : { parameters: {}, initial: {} };
  const parameters = (system.parameters || []).map((p) => ({ ...p, value: wanted.parameters[p.name] ?? p.value }));
  const body = { system: { ...system, parameters }, format, initial: wanted.initial };
  if (wanted.t_end) body.t_end = wanted.t_end;
  return body;
}

function fileName(response, format) {
  const match = /filename="([^"]+)"/.exec(response.headers.get("content-disposition") || "");
  return match ? match[1] : `system.${format}`;
}

function post(body) {
  // one job at a time per session: while a simulation of this page runs, wait as the server asks
  return fetchRetrying("/api/export", {
    method: "POST",
    headers: { "content-type": "application/json" },
    body: JSON.stringify(body),
  });
}

async function download(format, button) {
  button.disabled = true;
  status.textContent = "Preparing the file…";
  try {
    const response = await post(request(format));
    if (!response.ok) {
      const answer = await response.json().catch(() => ({}));
      status.textContent = `Not exported: ${answer.detail || response.statusText}`;
      return;
    }
    const url = URL.createObjectURL(await response.blob());
    const link = document.createElement("a");
    link.href = url;
    link.download = fileName(response, format);
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
    status.textContent = `Saved ${link.download}.`;
  } catch (error) {
    status.textContent = `Not exported: ${error.message}`;
  } finally {
    button.disabled = false;
  }
}

for (const button of document.querySelectorAll("button[data-export-format]")) {
  button.addEventListener("click", () => download(button.dataset.exportFormat, button));
}
