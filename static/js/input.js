/**
 * input.js — a mechanism's canvas answering the pointer and the keyboard (animation.js).
 *
 * A body dragged (or the arrow keys while the canvas has focus; N picks the next body) moves along
 * its constraint and sets the initial coordinates through onDrag({q: value, ...}); the velocity
 * handle dragged (or Shift with the arrow keys) sets the initial rates (drag.js finds the values).
 * A 3-D view turns when the background is dragged.  A touch that lands on a body drags it; any other
 * touch scrolls the page.
 */

export class Input {
  constructor(player) {
    this.player = player;
    this.bindPointer();
    this.bindKeys();
  }

  pointer(event) {
    const r = this.player.canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    return [(event.clientX - r.left) * dpr, (event.clientY - r.top) * dpr];
  }

  bindPointer() {
    const c = this.player.canvas;
    // a touch that lands on a body drags it; any other touch scrolls the page (touch-action: pan-y)
    c.addEventListener("touchstart", (e) => {
      const t = e.touches[0];
      if (t && (this.player.drag.onHandle(...this.pointer(t)) || this.player.drag.grab(...this.pointer(t)) >= 0)) e.preventDefault();
    }, { passive: false });
    c.addEventListener("pointerdown", (e) => {
      const [x, y] = this.pointer(e);
      const h = this.player.onDrag ? this.player.drag.onHandle(x, y) : null;
      const k = h ? -1 : this.player.drag.grab(x, y);
      if (h) {
        this.player.pause();
        // the pointer's offset from the handle's centre stays put during the drag; the handle's label
        // (arrows.js labelHandle) has done its work once the reader has held the handle
        this.player.dragging = { rates: h.k, dx: h.x - x, dy: h.y - y };
        this.player.handleHeld = true;
      } else if (k >= 0 && this.player.onDrag) {
        this.player.pause();
        this.player.selected = k;
        this.player.dragging = { k };
        if (this.player.index !== 0) this.player.seek(0);
      } else if (this.player.dim === 3 && e.pointerType !== "touch") {
        this.player.dragging = { rotate: true, x, y, yaw: this.player.camera.view.yaw, pitch: this.player.camera.view.pitch };
      } else return;
      c.setPointerCapture(e.pointerId);
      e.preventDefault();
    });
    c.addEventListener("pointermove", (e) => {
      if (!this.player.dragging) {
        if (this.player.onDrag && e.pointerType === "mouse") {
          const [x, y] = this.pointer(e);
          c.style.cursor = this.player.drag.onHandle(x, y) || this.player.drag.grab(x, y) >= 0 ? "grab" : "";
        }
        return;
      }
      const [x, y] = this.pointer(e);
      if (this.player.dragging.rotate) {
        const d = this.player.dragging;
        this.player.camera.turn(d, x - d.x, y - d.y, window.devicePixelRatio || 1);
        this.player.fit();
        this.player.draw(this.player.index);
        return;
      }
      if (this.player.dragging.rates !== undefined) {
        const d = this.player.dragging, values = this.player.drag.solveRates(d.rates, x + d.dx, y + d.dy);
        if (values) this.player.onDrag(values);
        return;
      }
      const values = this.player.drag.solve(this.player.dragging.k, x, y);
      if (values) this.player.onDrag(values);
    });
    const end = () => { this.player.dragging = null; };
    c.addEventListener("pointerup", end);
    c.addEventListener("pointercancel", end);
  }

  bindKeys() {
    const c = this.player.canvas;
    c.addEventListener("focus", () => { this.player.focused = true; if (this.player.run) this.player.draw(this.player.index); });
    c.addEventListener("blur", () => { this.player.focused = false; if (this.player.run) this.player.draw(this.player.index); });
    c.addEventListener("keydown", (e) => {
      if (!this.player.run || !this.player.onDrag || !this.player.masses.length) return;
      if (e.key === "n" || e.key === "N") {
        this.player.selected = (this.player.selected + 1) % this.player.masses.length;
        this.player.draw(this.player.index);
        this.say(`${this.player.spec.points[this.player.masses[this.player.selected]].label} selected`);
        e.preventDefault();
        return;
      }
      const keys = { ArrowRight: [0, 1], ArrowUp: [1, 1], ArrowLeft: [0, -1], ArrowDown: [1, -1] };
      if (!(e.key in keys)) return;
      e.preventDefault();
      if (!e.shiftKey) {
        // the body moves the way the arrow points on screen: the initial coordinates that bring it
        // nearest a point a few pixels that way (along its constraint, if it has one)
        const names = (this.player.ownersOf[this.player.selected] || []).filter((q) => this.player.controls && this.player.controls(q));
        if (!names.length) return;
        const now = Object.fromEntries(names.map((q) => [q, this.player.controls(q).value]));
        const [px, py] = this.player.drag.placed(this.player.selected, now);
        const dx = { ArrowRight: 1, ArrowLeft: -1 }[e.key] || 0, dy = { ArrowDown: 1, ArrowUp: -1 }[e.key] || 0;
        const PIXELS = 6;
        const values = this.player.drag.solve(this.player.selected, px + PIXELS * dx, py + PIXELS * dy);
        const moved = values && names.filter((q) => Math.abs(values[q] - now[q]) > 1e-9 * Math.max(1, Math.abs(now[q])));
        if (!moved || !moved.length) { this.say("This body cannot move that way from here; try another arrow."); return; }
        this.player.pause();
        if (this.player.index !== 0) this.player.seek(0);
        this.player.onDrag(Object.fromEntries(moved.map((q) => [q, values[q]])));
        this.say(moved.map((q) => `${this.player.run.data.labels[q] || q} starts at ${Number(values[q].toPrecision(4))}`).join(", "));
        return;
      }
      // Shift: the body's initial rates, Right/Left the first, Up/Down the second (or the first if it has one)
      const names = this.player.drag.rateNames(this.player.selected);
      if (!names.length) return;
      const [which, sign] = keys[e.key];
      const q = names[Math.min(which, names.length - 1)];
      const r = this.player.controls(q);
      const step = (r.max - r.min) / 200;
      const value = Math.min(r.max, Math.max(r.min, r.value + sign * step));
      this.player.pause();
      if (this.player.index !== 0) this.player.seek(0);
      this.player.onDrag({ [q]: value });
      this.say(`${this.player.run.data.labels[q] || q} starts at ${Number(value.toPrecision(4))}`);
    });
  }

  say(text) {
    if (this.player.dragStatus) this.player.dragStatus.textContent = text;
  }
}
