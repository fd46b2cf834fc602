/**
 * embed.js — the entry module of an embed page (templates/embed.html, app/web/embed.py).
 *
 * The scene's simulation alone: the animation, its controls and at most one plot panel,
 * bound as on the scene page (simulation.js); no derivation to typeset or fold.
 */
import { fetchJSON } from "./api.js";
import { connectSimulation } from "./simulation.js";

const data = JSON.parse(document.getElementById("scene-data").textContent);
const root = document.getElementById("simulation");
connectSimulation({
  form: document.getElementById("controls"),
  root,
  data,
  urls: {
    simulate: root.dataset.simulateUrl,
    workPrecision: root.dataset.workPrecisionUrl,
    modes: (parameters) => fetchJSON(root.dataset.modesUrl, { body: { parameters } }),
    poincare: (request) => fetchJSON(root.dataset.poincareUrl, { body: request }),
  },
  status: document.getElementById("run-status"),
});
