// The presentation page: one slide per shot; keys move between slides, each shot plays on entering, then holds, loops or goes on.
(() => {
  'use strict';
  const data = JSON.parse(document.getElementById('vibra-present').textContent);
  const $ = id => document.getElementById(id);
  const slides = [...document.querySelectorAll('.slide')];
  const videos = slides.map(s => s.querySelector('video'));
  const count = slides.length;
  const speakerMode = location.hash === '#speaker';
  const openedAt = performance.now();
  // Videos stay loaded this many slides either side of the current one, so
  // entering a slide is instant (each shot starts on a keyframe) and a long
  // lecture does not hold every video at once.
  const kNearby = 2;
  let current = -1, typed = '', loops = 0, speaker = null, shown = null;
  let blocked = false;  // the current slide speaks, and waits for a key before it plays
  // The time of the frame on screen, as the browser presented it: a paused
  // video's currentTime may lie a frame before it.
  let presented = 0;
  videos.forEach(v => {
    if (!v.requestVideoFrameCallback) return;
    const on = (now, frame) => {
      if (v === videos[current]) presented = frame.mediaTime;
      v.requestVideoFrameCallback(on);
    };
    v.requestVideoFrameCallback(on);
  });

  // A slide's own clock: simulated time at video time s, as the render
  // evaluates it (scenes/timing/time_map.cpp): steady, or through the pacing pieces.
  const simulatedTime = (shot, s) => {
    const k = Math.min(shot.frames - 1, Math.max(0, Math.floor(s * data.fps + 1e-3)));
    const map = shot.clock.map, v = k / data.fps;
    if (!map) return k * shot.clock.interval;
    let i = 0;
    while (i + 1 < map.length && map[i + 1][0] <= v) i++;
    const end = i + 1 < map.length ? map[i + 1][1] : Infinity;
    return Math.min(end, map[i][1] + (v - map[i][0]) * map[i][2]);
  };

  function loadNearby(i) {
    videos.forEach((v, k) => {
      const near = Math.abs(k - i) <= kNearby;
      if (near && !v.getAttribute('src')) {
        v.preload = 'auto';
        v.src = v.dataset.src;
      } else if (!near && v.getAttribute('src')) {
        v.pause();
        v.removeAttribute('src');
        v.load();  // lets the browser drop the video
      }
    });
  }

  // Entering a slide plays its shot from the start.
  function go(i) {
    i = Math.max(0, Math.min(count - 1, i));
    if (i === current) return;
    if (current >= 0) {
      videos[current].pause();
      slides[current].hidden = true;
    }
    current = i;
    slides[i].hidden = false;
    loadNearby(i);
    const v = videos[i], shot = data.slides[i];
    v.loop = shot.then === 'loop' && !(shot.intro > 0);  // a whole loop seamlessly; an intro by 'ended'
    v.currentTime = 0;
    presented = 0;
    blocked = false;
    // A browser plays sound only after a key or a click on the page: a
    // speaking first slide waits for P (or any slide's key) rather than
    // playing on without its voice.
    v.play().catch(() => { if (shot.sound) { blocked = true; showStatus(); } });
    history.replaceState(null, '', '#' + (i + 1));
    $('progress-bar').style.width = (100 * (i + 1) / count) + '%';
    showStatus();
    tellSpeaker();
  }

  // At a shot's end: hold its last frame (the ended video shows it), play
  // the loop again from after the intro, or go on by itself.
  videos.forEach((v, k) => v.addEventListener('ended', () => {
    if (k !== current) return;
    const shot = data.slides[k];
    if (shot.then === 'next' && k + 1 < count) go(k + 1);
    else if (shot.then === 'loop') {
      loops++;
      v.currentTime = shot.intro;
      v.play().catch(() => {});
    }
    tellSpeaker();
  }));

  const showStatus = () => {
    $('status').textContent = typed ? 'go to ' + typed
                                    : (current + 1) + ' / ' + count + (blocked ? ' · P plays it, with sound' : '');
  };
  const toggle = id => { $(id).hidden = !$(id).hidden; };
  function pauseOrPlay() {
    const v = videos[current];
    blocked = false;
    if (v.paused && !v.ended) v.play().catch(() => {});
    else v.pause();
    showStatus();
    tellSpeaker();
  }
  function fullScreen() {
    if (document.fullscreenElement) document.exitFullscreen();
    else document.documentElement.requestFullscreen().catch(() => {});
  }
  function jumpToTyped() {
    const n = parseInt(typed, 10);
    typed = '';
    if (n >= 1 && n <= count) go(n - 1);
    showStatus();
  }

  // The keys presenters expect (reveal.js, PowerPoint; clickers send PageDown and PageUp).
  const next = () => go(current + 1), back = () => go(current - 1);
  const keyActions = {
    ArrowRight: next, ArrowDown: next, ' ': next, PageDown: next,
    ArrowLeft: back, ArrowUp: back, PageUp: back,
    Home: () => go(0), End: () => go(count - 1), Enter: jumpToTyped,
    f: fullScreen, b: () => toggle('black'), '.': () => toggle('black'), p: pauseOrPlay,
    s: openSpeaker, h: () => toggle('about'), '?': () => toggle('about'),
  };
  function press(key) {
    if (/^[0-9]$/.test(key)) {
      typed = (typed + key).slice(-6);
      return showStatus();
    }
    const action = keyActions[key.length === 1 ? key.toLowerCase() : key];
    if (!action) return false;
    if (key !== 'Enter') typed = '';
    action();
    return true;
  }

  // The speaker view: a second window of this page (#speaker), kept in step
  // by messages, which pass between file: pages where other channels may not.
  function openSpeaker() {
    if (speakerMode) return;
    if (!speaker || speaker.closed)
      speaker = window.open(location.href.replace(/#.*$/, '') + '#speaker', 'vibra-speaker', 'width=1000,height=640');
    tellSpeaker();
  }
  function tellSpeaker() {
    if (!speaker || speaker.closed || current < 0) return;
    const v = videos[current];
    const time = v.requestVideoFrameCallback ? presented : v.currentTime;
    speaker.postMessage({ vibra: 'state', slide: current, time, paused: v.paused,
                          elapsed: (performance.now() - openedAt) / 1000 }, '*');
  }

  const clockText = s => Math.floor(s / 60) + ':' + String(Math.floor(s % 60)).padStart(2, '0');
  function showSpeaker(state) {
    const shot = data.slides[state.slide], after = data.slides[state.slide + 1];
    shown = state;
    $('speaker-title').textContent = (state.slide + 1) + ' / ' + count + '  ' + shot.title;
    $('speaker-notes').replaceChildren(...shot.notes.map(n => Object.assign(document.createElement('li'), { textContent: n })));
    $('speaker-next-title').textContent = after ? after.title : '(the end)';
    if (after) $('speaker-next-still').src = after.still;
    $('speaker-next-still').hidden = !after;
    $('speaker-elapsed').textContent = clockText(state.elapsed);
    $('speaker-time').textContent = shot.clock ? 't = ' + simulatedTime(shot, state.time).toFixed(2) : '';
    $('speaker-state').textContent = state.paused ? 'paused' : '';
  }

  window.addEventListener('message', e => {
    const m = e.data || {};
    if (m.vibra === 'state' && speakerMode) showSpeaker(m);
    else if (m.vibra === 'key' && !speakerMode) press(m.key);
    else if (m.vibra === 'hello' && !speakerMode) tellSpeaker();
  });
  document.addEventListener('keydown', e => {
    if (e.ctrlKey || e.altKey || e.metaKey) return;
    if (speakerMode) {  // the speaker's keys drive the main window
      if (window.opener) window.opener.postMessage({ vibra: 'key', key: e.key }, '*');
      if (keyActions[e.key] || /^[0-9]$/.test(e.key)) e.preventDefault();
      return;
    }
    if (press(e.key) !== false) e.preventDefault();
  });
  window.addEventListener('hashchange', () => {
    const n = parseInt(location.hash.slice(1), 10);
    if (!speakerMode && n >= 1 && n <= count) go(n - 1);
  });

  if (speakerMode) {
    document.body.classList.add('speaker');
    $('speaker').hidden = false;
    if (window.opener) window.opener.postMessage({ vibra: 'hello' }, '*');
  } else {
    const n = parseInt(location.hash.slice(1), 10);  // a reload stays on its slide
    go(n >= 1 && n <= count ? n - 1 : 0);
    setInterval(tellSpeaker, 250);  // the speaker's clocks run on
  }
  window.vibraPresent = { get current() { return current; }, get loops() { return loops; }, get typed() { return typed; },
                          get speaker() { return speaker; }, get shown() { return shown; },
                          get presented() { return presented; }, videos, go, press };
})();
