/**
 * api.js — JSON requests to our own API for panels that fetch their own data (modes.js, poincare.js).
 *
 *   fetchJson(url, body?)   GET (no body) or POST the body; resolves to the JSON answer.  A 429 or
 *                           503 is retried after its Retry-After (a few times); any other refusal
 *                           rejects with Error(the API's "detail").
 */
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

export async function fetchJson(url, body = undefined) {
  for (let attempt = 0; ; attempt++) {
    const res = await fetch(url, body === undefined
      ? { headers: { Accept: "application/json" } }
      : { method: "POST", headers: { "Content-Type": "application/json", Accept: "application/json" }, body: JSON.stringify(body) });
    let answer = null;
    try { answer = await res.json(); } catch { answer = null; }
    if (res.ok) return answer;
    if ((res.status === 429 || res.status === 503) && attempt < 8) {
      await sleep(1000 * Number(res.headers.get("Retry-After") || 1));
      continue;
    }
    const detail = answer && answer.detail ? answer.detail : `the server answered ${res.status}`;
    throw new Error(typeof detail === "string" ? detail : JSON.stringify(detail));
  }
}
