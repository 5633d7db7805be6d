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

// A transparent canvas of width x height pixels to draw into, made by ctx's
// makeCanvas where it has one (the tests' recording context), else as the browser does.
function newCanvas(ctx, width, height) {
  if (ctx.makeCanvas) return ctx.makeCanvas(width, height);
  return typeof OffscreenCanvas !== 'undefined' ? new OffscreenCanvas(width, height)
                                                : Object.assign(document.createElement('canvas'), { width, height });
}

// A group: a transparent layer as large as the canvas, drawn into until it
// is painted on the layer below.
function newLayer(ctx) {
  return newCanvas(ctx, ctx.canvas.width, ctx.canvas.height).getContext('2d');
}

// The path filled with a tile drawn by its own operations (DrawCommands::fill_pattern):
// a canvas pattern, repeated or once, placed by the tile-to-page matrix.
function fillPattern(s, n, i) {
  const [width, height, repeat, smooth, xx, yx, xy, yy, x0, y0, evenOdd, count, first, strings] = n.slice(i, i + 14);
  const tile = newCanvas(s.ctx, Math.max(1, width), Math.max(1, height));
  const tileStrings = s.strings.slice(first, first + strings);
  replayInto({ ctx: tile.getContext('2d'), layers: [], strings: tileStrings }, n, i + 14, i + 14 + count);
  const pattern = s.ctx.createPattern(tile, repeat ? 'repeat' : 'no-repeat');
  pattern.setTransform({ a: xx, b: yx, c: xy, d: yy, e: x0, f: y0 });
  s.ctx.imageSmoothingEnabled = Boolean(smooth);
  s.ctx.fillStyle = pattern;
  s.ctx.fill(evenOdd ? 'evenodd' : 'nonzero');
  s.ctx.imageSmoothingEnabled = true;
  return i + 14 + count;
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
  /* fillPattern */ fillPattern,
];

// Draws the operations (numbers: an array or Float64Array; strings: the
// list joined by '\n') on ctx, whose transform is left the identity.
function replayCommands(ctx, numbers, joinedStrings) {
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  replayInto({ ctx, layers: [], strings: (joinedStrings || '').split('\n') }, numbers, 0, numbers.length);
}

// The operations of numbers[begin, end) drawn in state's context.
function replayInto(state, numbers, begin, end) {
  for (let i = begin; i < end;) {
    const operation = kOperations[numbers[i]];
    if (!operation) throw new Error(`drawing operation ${numbers[i]} at ${i} is unknown`);
    i = operation(state, numbers, i + 1);
  }
}

if (typeof module !== 'undefined') module.exports = { replayCommands, kOperationCount: kOperations.length };
