// The room page's and the face lab's drawing loop: once per animation frame
// at most at the room's tick rate, the canvas kept at its CSS size times the
// device pixel ratio (at most 2).

/** Calls `draw(width, height, pixelRatio, nowMs)` from now on, in CSS pixels. */
export function startDrawLoop(canvas, draw) {
  let lastDraw = -Infinity;
  const frame = (now) => {
    requestAnimationFrame(frame);
    // Faces change at most at the room's tick rate (30 Hz): drawing more
    // often only burns the battery, or a software renderer's cores.
    if (now - lastDraw < 1000 / 32) return;
    lastDraw = now;
    const ratio = Math.min(2, window.devicePixelRatio || 1);
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(height * ratio);
    }
    draw(width, height, ratio, now);
  };
  requestAnimationFrame(frame);
}
