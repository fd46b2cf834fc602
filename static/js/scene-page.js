/**
 * scene-page.js — the entry module of a scene page (templates/scene.html).
 *
 * Typesets the server-rendered derivation (MathML until KaTeX has loaded), folds its
 * bookkeeping steps behind an "all steps" toggle, prepares it for printing, and binds the
 * controls to the simulation.  Everything it needs is in the page:
 * <script type="application/json" id="scene-data"> and data-* URLs on #simulation.
 */
import { foldSteps, printReady, whenTypeset } from "./derivation.js";
import { connectScene } from "./simulation.js";
import { keyboardScroll } from "./scrollboxes.js";
import { foldPanels } from "./fold.js";
import { bindEmbedOffer, bindViewLink, restoreControls, restoreView } from "./statelink.js";

const data = JSON.parse(document.getElementById("scene-data").textContent);
foldSteps(document);
printReady();
whenTypeset(document);
keyboardScroll(document);
foldPanels(document);

const root = document.getElementById("simulation");
// a link to a view: its settings before the first run, the rest (instant, panels, practice step) after
restoreControls();
if (root) connectScene(root, data);
restoreView();
bindViewLink();
bindEmbedOffer();
