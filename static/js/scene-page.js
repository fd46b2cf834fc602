/**
 * scene-page.js — the entry module of a scene page (templates/scene.html).
 *
 * Typesets the server-rendered derivation, prepares it for printing, and binds
 * the controls to the simulation panels.  Everything it needs is in the page:
 * <script type="application/json" id="scene-data"> and data-* URLs on #simulation.
 */
import { printReady, typeset } from "./derivation.js";
import { connectSimulation } from "./simulation.js";

const data = JSON.parse(document.getElementById("scene-data").textContent);
const errors = typeset(document);
document.body.dataset.katexErrors = String(errors);
printReady();

const root = document.getElementById("simulation");
if (root && window.Plotly) {
  connectSimulation({
    form: document.getElementById("controls"),
    root,
    data,
    urls: { simulate: root.dataset.simulateUrl, workPrecision: root.dataset.workPrecisionUrl },
    status: document.getElementById("run-status"),
  });
} else if (root) {
  document.querySelector("#run-status .message").textContent =
    "The plotting library is missing: run scripts/assets.sh (it copies plotly.js into static/vendor).";
}
