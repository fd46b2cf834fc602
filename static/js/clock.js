/**
 * clock.js — the animation's clock: simulated time advancing with the wall clock at a chosen speed,
 * one requestAnimationFrame callback per display frame, looping at the run's end.
 *
 *   const clock = new Clock({ speed: () => 1, end: () => seconds or null, onTime: (t) => … });
 *   clock.start(t); clock.stop(); clock.playing
 */
export class Clock {
  constructor({ speed, end, onTime }) {
    this.speed = speed;
    this.end = end; // the run's last instant, or null when there is no run (the clock then stops)
    this.onTime = onTime;
    this.playing = false;
    this.tick = this.tick.bind(this);
  }

  start(t) {
    if (this.playing) return;
    this.playing = true;
    this.simTime = t;
    this.last = null;
    requestAnimationFrame(this.tick);
  }

  stop() {
    this.playing = false;
  }

  tick(now) {
    const end = this.end();
    if (!this.playing || end === null) return;
    if (this.last !== null) this.simTime += ((now - this.last) / 1000) * this.speed();
    this.last = now;
    if (this.simTime > end) this.simTime = 0; // loop
    this.onTime(this.simTime);
    requestAnimationFrame(this.tick);
  }
}
