// Replays a frame's operations recorded by web/canvas/draw_commands.hpp on the browser's 2D canvas context.
'use strict';

// Cairo's joins and caps by number (web/shim/cairo.h), and the composite
// operators DrawCommands::composite hands on.
const kJoins = ['miter', 'round', 'bevel'];
const kCaps = ['butt', 'round', 'square'];
const kComposites = ['source-over', 'copy', 'destination-out'];

function rgba(n, i) {
  const c = k => Math.round(255 * Math.min(1, Math.max(0, n[i + k])));
  return `rgba(${c(0)},${c(1)},${c(2)},${Math.min(1, Math.max(0, n[i + 3]))})`;
}

// The pen of a stroke or a text run: colour, width, join, cap, then its
// user matrix, set as the context's transform. Returns the index after it.
function setPen(ctx, n, i, style) {
  ctx[style] = rgba(n, i);
  ctx.lineWidth = n[i + 4];
  ctx.lineJoin = kJoins[n[i + 5]];
  ctx.lineCap = kCaps[n[i + 6]];
  ctx.setTransform(n[i + 7], n[i + 8], n[i + 9], n[i + 10], n[i + 11], n[i + 12]);
  return i + 13;
}

// A group: a transparent layer as large as the canvas, drawn into until it
// is painted on the layer below.
function newLayer(ctx) {
  const canvas = typeof OffscreenCanvas !== 'undefined' ? new OffscreenCanvas(ctx.canvas.width, ctx.canvas.height)
                                                        : Object.assign(document.createElement('canvas'),
                                                                        { width: ctx.canvas.width, height: ctx.canvas.height });
  return canvas.getContext('2d');
}

// Each operation reads its numbers from n at i and returns the index after them.
const kOperations = [
  /* save */ (s, n, i) => (s.ctx.save(), i),
  /* restore */ (s, n, i) => (s.ctx.restore(), i),
  /* beginPath */ (s, n, i) => (s.ctx.beginPath(), i),
  /* moveTo */ (s, n, i) => (s.ctx.moveTo(n[i], n[i + 1]), i + 2),
  /* lineTo */ (s, n, i) => (s.ctx.lineTo(n[i], n[i + 1]), i + 2),
  /* closePath */ (s, n, i) => (s.ctx.closePath(), i),
  /* fill */ (s, n, i) => {
    s.ctx.fillStyle = rgba(n, i);
    s.ctx.fill(n[i + 4] ? 'evenodd' : 'nonzero');
    return i + 5;
  },
  /* stroke */ (s, n, i) => {
    i = setPen(s.ctx, n, i, 'strokeStyle');
    const count = n[i], offset = n[i + 1];
    s.ctx.setLineDash(Array.from(n.slice(i + 2, i + 2 + count)));
    s.ctx.lineDashOffset = offset;
    s.ctx.stroke();
    s.ctx.setTransform(1, 0, 0, 1, 0, 0);  // paths are built in device pixels
    s.ctx.setLineDash([]);
    return i + 2 + count;
  },
  /* clip */ (s, n, i) => (s.ctx.clip(n[i] ? 'evenodd' : 'nonzero'), i + 1),
  /* paint */ (s, n, i) => {
    s.ctx.fillStyle = rgba(n, i);
    s.ctx.fillRect(0, 0, s.ctx.canvas.width, s.ctx.canvas.height);
    return i + 4;
  },
  /* text */ (s, n, i) => {
    const stroked = n[i];
    i = setPen(s.ctx, n, i + 1, stroked ? 'strokeStyle' : 'fillStyle');
    s.ctx.font = s.strings[n[i + 2]];
    s.ctx.textBaseline = 'alphabetic';
    if (stroked) s.ctx.strokeText(s.strings[n[i + 3]], n[i], n[i + 1]);
    else s.ctx.fillText(s.strings[n[i + 3]], n[i], n[i + 1]);
    s.ctx.setTransform(1, 0, 0, 1, 0, 0);
    return i + 4;
  },
  /* composite */ (s, n, i) => ((s.ctx.globalCompositeOperation = kComposites[n[i]]), i + 1),
  /* pushGroup */ (s, n, i) => {
    s.layers.push(s.ctx);
    s.ctx = newLayer(s.ctx);
    return i;
  },
  /* popGroupPaint */ (s, n, i) => {
    const layer = s.ctx;
    if (!s.layers.length) return i + 1;
    s.ctx = s.layers.pop();
    s.ctx.save();
    s.ctx.globalAlpha = n[i];
    s.ctx.drawImage(layer.canvas, 0, 0);
    s.ctx.restore();
    return i + 1;
  },
];

// Draws the operations (numbers: an array or Float64Array; strings: the
// list joined by '\n') on ctx, whose transform is left the identity.
function replayCommands(ctx, numbers, joinedStrings) {
  const state = { ctx, layers: [], strings: (joinedStrings || '').split('\n') };
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  for (let i = 0; i < numbers.length;) {
    const operation = kOperations[numbers[i]];
    if (!operation) throw new Error(`drawing operation ${numbers[i]} at ${i} is unknown`);
    i = operation(state, numbers, i + 1);
  }
}

if (typeof module !== 'undefined') module.exports = { replayCommands, kOperationCount: kOperations.length };
