/**
 * embed.js — the entry module of an embed page (templates/embed.html, app/web/embed.py).
 *
 * The scene's simulation alone: the animation, its controls and at most one plot panel,
 * bound as on the scene page (simulation.js); no derivation to typeset or fold.
 */
import { connectScene } from "./simulation.js";

const data = JSON.parse(document.getElementById("scene-data").textContent);
connectScene(document.getElementById("simulation"), data);
