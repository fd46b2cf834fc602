/**
 * embed.js — the entry module of an embed page (templates/embed.html, app/web/pages/embed.py).
 *
 * The scene's simulation alone: the animation, its controls and at most one plot panel,
 * bound as on the scene page (simulation.js); no derivation to typeset or fold.  A fragment
 * in the address (the scene page's "Put this in a course page" code, or "Link to this view")
 * is read as on the scene page (statelink.js): its settings before the first run, its instant after.
 */
import { connectScene } from "./simulation.js";
import { restoreControls, restoreView } from "./statelink.js";

const data = JSON.parse(document.getElementById("scene-data").textContent);
restoreControls();
connectScene(document.getElementById("simulation"), data);
restoreView();
