// Every built-in scene set up and drawn by the browser build's scene code (vibra_live.js) under node, and a bad value refused as the CLI refuses it.
'use strict';
const { execFileSync, spawnSync } = require('child_process');
const path = require('path');
const { check, finish, coreJs, vibra } = require('./check_support.js');
const createVibraLive = require(coreJs);
const { replayCommands } = require(path.join(__dirname, '..', '..', 'web/canvas/replay.js'));

// node has no canvas to measure text with: every character 0.6 em wide, ink to the cap height.
const measuring = {
  font: '',
  measureText(text) {
    const size = parseFloat(/([\d.]+)px/.exec(this.font)[1]), width = 0.6 * size * [...text].length;
    return { width, actualBoundingBoxLeft: 0, actualBoundingBoxRight: width, actualBoundingBoxAscent: 0.73 * size,
             actualBoundingBoxDescent: 0 };
  },
};

const help = execFileSync(vibra, ['render', '--help'], { encoding: 'utf8' });

// A 2D context that keeps what replay.js asks of it: the fills, each with the style it filled with,
// and the canvases made for patterns' tiles, each one such a context too.
function recordingContext(width, height) {
  const ctx = { canvas: { width, height }, fills: [], fillStyle: '', calls: 0 };
  const recording = new Proxy(ctx, { get: (t, name) => (name in t ? t[name] : () => { t.calls++; }) });
  ctx.canvas.getContext = () => recording;
  ctx.makeCanvas = (w, h) => recordingContext(w, h).canvas;
  ctx.createPattern = (canvas, repetition) => ({ tile: canvas.getContext(), repetition, setTransform(m) { this.m = m; } });
  ctx.fill = () => ctx.fills.push(ctx.fillStyle);
  return recording;
}

createVibraLive({ vibraMeasureContext: measuring }).then(core => {
  const names = ['bouncing_ball', 'bumpy_road', 'elastic_pendulum', 'orbit', 'pendulum', 'pendulum_book', 'rlc',
                 'sliding_box', 'spring', 'spring_dashpot', 'washing_machine'];
  for (const name of names) {
    const opened = core.ccall('vibra_scene_open', 'number', ['string', 'string'], [name, 'size=640x360']);
    const end = core._vibra_scene_end_time();
    const drawn = opened === 0 && core._vibra_scene_draw(end / 2, 1) === 0;
    const strings = core.UTF8ToString(core._vibra_scene_strings());
    check(drawn && core._vibra_scene_number_count() > 1000 && strings.includes('DejaVu Sans'),
          `${name}: set up and drawn at t = ${end / 2} (${core._vibra_scene_number_count()} numbers, text runs in DejaVu Sans)`
          + (drawn ? '' : ': ' + core.UTF8ToString(core._vibra_scene_error())));
    // Every fill reaches the canvas with a colour or a pattern, and nothing drawn natively is dropped.
    const at = core._vibra_scene_numbers() >> 3;
    const ctx = recordingContext(640, 360);
    replayCommands(ctx, core.HEAPF64.subarray(at, at + core._vibra_scene_number_count()), strings);
    const patterns = ctx.fills.filter(style => typeof style === 'object');
    check(core._vibra_scene_dropped() === 0 && ctx.fills.length > 0 && ctx.fills.every(style => style),
          `${name}: every fill drawn with its source, none dropped (${ctx.fills.length} fills, `
          + `${patterns.length} with a pattern, ${core._vibra_scene_dropped()} dropped)`);
    if (name === 'bumpy_road') {
      // The ground's hatched band: a repeated tile painted pale and crossed by its hatches, as natively.
      const hatch = patterns.find(p => p.repetition === 'repeat' && p.tile.fills.length === 0 && p.tile.calls > 3);
      check(Boolean(hatch), "bumpy_road: the ground's band filled with its hatch tile, repeated");
    }
  }
  const refused = core.ccall('vibra_scene_open', 'number', ['string', 'string'], ['pendulum', 'alpha=-1']);
  const cli = spawnSync(vibra, ['render', 'pendulum', '--set', 'alpha=-1', '--at', '0', '-o', 'never.png'], { encoding: 'utf8' });
  const reason = core.UTF8ToString(core._vibra_scene_error());
  check(refused === 2 && cli.status === 2 && cli.stderr.trim() === `vibra: error: ${reason}`,
        `a bad value is refused with the CLI's reason: ${reason}`);
  check(names.every(n => help.includes(n)), 'the scenes drawn are built-in ones `vibra render --help` lists');
  finish();
});
