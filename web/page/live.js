// The live page's script: controls built from the CLI's key table, each change re-solved and drawn by the WebAssembly scene code.
'use strict';

const config = JSON.parse(document.getElementById('config').textContent);
const $ = id => document.getElementById(id);
const page = { core: null, keys: [], values: {}, t: 0, playing: false, frame: 0, startedAt: 0, startFrame: 0,
               end: 0, frames: 1, fps: 30, lastLatency: 0, drawTimes: [] };

// One KEY=VALUE a line: the command line's settings, then the keys the page changed (a later one wins),
// so that the scene's caption names what the command line and the page set, as a render's does.
function settingsText(values) {
  const lines = config.base.slice();
  for (const key of page.keys) if (values[key.name] !== startValue(key)) lines.push(`${key.name}=${values[key.name]}`);
  return lines.join('\n');
}

// Sets the scene up with these values; the CLI's one-line reason when they are refused.
function open(values) {
  const code = config.sceneText
    ? page.core.ccall('vibra_scene_open_file', 'number', ['string', 'string', 'string'],
                      [config.scene, config.sceneText, settingsText(values)])
    : page.core.ccall('vibra_scene_open', 'number', ['string', 'string'], [config.scene, settingsText(values)]);
  if (code !== 0) return page.core.UTF8ToString(page.core._vibra_scene_error());
  page.end = page.core._vibra_scene_end_time();
  page.frames = page.core._vibra_scene_frame_count();
  page.fps = page.core._vibra_scene_fps();
  $('time').max = String(page.end);
  return '';
}

// Draws the frame at t through the scene code, and hands its operations to the canvas. At once (the label
// chain starting at t) while a control or the scrubber moves; as the still at t (its chain's frames before
// it drawn unseen) once they rest, a moment later.
function draw(t, wholeChain = false) {
  const started = performance.now();
  page.t = Math.min(Math.max(t, 0), page.end);
  clearTimeout(page.settle);
  page.settled = wholeChain;
  if (!wholeChain && !page.playing) page.settle = setTimeout(() => draw(page.t, true), 150);
  if (page.core._vibra_scene_draw(page.t, wholeChain ? 1 : 0) !== 0) {
    refuse(page.core.UTF8ToString(page.core._vibra_scene_error()));
    return;
  }
  const core = page.core;
  const count = core._vibra_scene_number_count();
  const at = core._vibra_scene_numbers() >> 3;
  const numbers = core.HEAPF64.subarray(at, at + count);
  replayCommands($('frame').getContext('2d'), numbers, core.UTF8ToString(core._vibra_scene_strings()));
  page.drawTimes.push(performance.now() - started);
  $('time').value = String(page.t);
  $('time_shown').textContent = `t = ${page.t.toFixed(3)}`;
  updateShare();
}

function refuse(reason) {
  $('refusal').hidden = !reason;
  $('refusal').textContent = reason;
}

// A changed value: re-solved at once and drawn at the same time, or refused with the CLI's reason.
function change(name, value, input) {
  const started = performance.now();
  const values = Object.assign({}, page.values, { [name]: value });
  const reason = open(values);
  input.setAttribute('aria-invalid', reason ? 'true' : 'false');
  refuse(reason);
  if (reason) {
    open(page.values);  // the last good state stays on the page
    return;
  }
  page.values = values;
  draw(Math.min(page.t, page.end));
  syncControls(name, value);
  page.lastLatency = performance.now() - started;
}

function syncControls(name, value) {
  for (const input of document.querySelectorAll(`[data-key="${name}"]`)) if (input.value !== value) input.value = value;
}

// A key's value as the scene starts: its own setting, else the model's default ('' for a key unset, shown '-').
const startValue = key => String(config.initial[key.name] ?? (key.default === '-' ? '' : key.default));

// A slider where the key's range is a span one can slide over; a number box always; a select for choices.
function sliderSpan(key) {
  const r = key.range;
  if (!r) return null;
  const current = Number(page.values[key.name] || 1);
  if (key.control === 'angle') return [Math.max(r.lo, -180), Math.min(r.hi, 180)];
  const lo = Math.max(r.lo, 0), hi = Math.min(r.hi, Math.max(1, Math.abs(current) * 4));
  return hi > lo ? [lo, hi] : null;
}

function controlFor(key) {
  const label = document.createElement('label');
  label.title = key.meaning;
  label.append(Object.assign(document.createElement('span'), { textContent: key.name + (key.unit ? ` (${key.unit})` : '') }));
  const value = page.values[key.name];
  const inputs = [];
  if (key.control === 'choice') {
    const select = document.createElement('select');
    for (const choice of key.choices) select.append(new Option(choice, choice, false, choice === value));
    inputs.push(select);
  } else {
    const span = sliderSpan(key);
    if (span) inputs.push(Object.assign(document.createElement('input'),
                                        { type: 'range', min: span[0], max: span[1], step: 'any', value }));
    // An unset key (no default: derived from others, or not used) says so rather than showing an empty box.
    inputs.push(Object.assign(document.createElement('input'),
                              { type: span ? 'number' : 'text', step: 'any', value, placeholder: 'unset' }));
  }
  for (const input of inputs) {
    input.dataset.key = key.name;
    input.dataset.kind = input.tagName === 'SELECT' ? 'select' : input.type;
    input.addEventListener('change', () => change(key.name, input.value, input));
    if (input.type === 'range') input.addEventListener('input', () => change(key.name, input.value, input));
    label.append(input);
  }
  return label;
}

// The state as a link: the keys that differ from the scene's own, and the time.
function stateHash() {
  const parts = [];
  for (const key of page.keys)
    if (page.values[key.name] !== startValue(key))
      parts.push(`${encodeURIComponent(key.name)}=${encodeURIComponent(page.values[key.name])}`);
  parts.push(`t=${Number(page.t.toPrecision(12))}`);
  return '#' + parts.join('&');
}

function updateShare() {
  $('share').href = stateHash();
  if (!$('command').hidden) $('command').textContent = renderCommand();
}

const shellWord = w => (/^[\w.,:=+\-/]+$/.test(w) ? w : `'${w.replace(/'/g, `'\\''`)}'`);

// The vibra render command that draws this frame as a still: the command line's settings the page did not
// change, then those it did.
function renderCommand() {
  const words = ['vibra', 'render', config.scene];
  const changed = page.keys.filter(key => page.values[key.name] !== startValue(key));
  for (const line of config.base)
    if (!changed.some(key => line.startsWith(key.name + '='))) words.push('--set', line);
  for (const key of changed) words.push('--set', `${key.name}=${page.values[key.name]}`);
  words.push('--at', String(Number(page.t.toPrecision(12))), '-o', `${config.name}.png`);
  return words.map(shellWord).join(' ');
}

// The values and time a share link holds (#Theta=60&alpha=0.4&t=3).
function readHash() {
  const values = {};
  for (const key of page.keys) values[key.name] = startValue(key);
  let t = 0;
  for (const part of location.hash.replace(/^#/, '').split('&').filter(Boolean)) {
    const [name, value] = part.split('=').map(decodeURIComponent);
    if (name === 't') t = Number(value);
    else if (page.keys.some(k => k.name === name)) values[name] = value;
  }
  return { values, t };
}

function applyHash() {
  const { values, t } = readHash();
  const reason = open(values);
  refuse(reason);
  if (reason) open(page.values);
  else page.values = values;
  for (const key of page.keys) syncControls(key.name, String(page.values[key.name]));
  if (!reason) for (const input of document.querySelectorAll('[data-key]')) input.setAttribute('aria-invalid', 'false');
  draw(Number.isFinite(t) ? t : 0);
}

// Playback: the scene's own frame clock (its speed and pauses), at the chosen speed.
function tick(now) {
  if (!page.playing) return;
  const speed = Number($('speed').value);
  const k = page.startFrame + Math.floor(((now - page.startedAt) / 1000) * page.fps * speed);
  if (k >= page.frames - 1) {
    page.playing = false;
    draw(page.end);
    return;
  }
  if (k !== page.frame) {
    page.frame = k;
    draw(page.core._vibra_scene_frame_time(k));
  }
  requestAnimationFrame(tick);
}

function play() {
  if (page.playing) return;
  page.playing = true;
  page.startFrame = page.t >= page.end ? 0 : frameOf(page.t);
  page.frame = -1;
  page.startedAt = performance.now();
  requestAnimationFrame(tick);
}

function frameOf(t) {
  let lo = 0, hi = page.frames - 1;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (page.core._vibra_scene_frame_time(mid) < t) lo = mid + 1; else hi = mid;
  }
  return lo;
}

async function start() {
  page.core = await createVibraLive();
  page.keys = JSON.parse(page.core.UTF8ToString(page.core.ccall('vibra_model_keys', 'number', ['string'], [config.model])))
    .concat(config.sceneKeys);  // the scene's own keys with a control: the comparison's values
  for (const key of page.keys) page.values[key.name] = startValue(key);
  for (const key of page.keys) $('keys').append(controlFor(key));
  $('play').addEventListener('click', play);
  $('pause').addEventListener('click', () => ((page.playing = false), draw(page.t)));
  $('time').addEventListener('input', () => ((page.playing = false), draw(Number($('time').value))));
  $('render_this').addEventListener('click', () => {
    $('command').hidden = false;
    $('command').textContent = renderCommand();
  });
  window.addEventListener('hashchange', applyHash);
  await document.fonts.load("16px 'DejaVu Sans'");
  await document.fonts.load("italic 16px 'DejaVu Sans'");
  applyHash();
  $('status').textContent = 'ready';
  document.body.dataset.ready = 'true';
}

window.vibraLivePage = page;
start().catch(e => {
  $('status').textContent = `the page could not start: ${e.message}`;
  document.body.dataset.ready = 'failed';
});
