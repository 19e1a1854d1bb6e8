'use strict';
// tetglow preview: polls /state, shows the newest image, and sends every change as a JSON merge
// patch on the settings (POST /settings). The server checks each value; its one-line error is
// shown here and the render goes on with the last good settings.
const $ = (id) => document.getElementById(id);
let settings = null;      // the last good settings, as the server holds them
let generation = -1;      // which of them the controls show
let shownImage = '', imageLoading = false;  // shownImage: the version and exposure on screen
let sending = false, queued = null;

// Colours are linear [0, 1] values shown as #rrggbb.
const hex = (rgb) => '#' + rgb.map((v) => Math.round(255 * Math.min(1, Math.max(0, v))).toString(16).padStart(2, '0')).join('');
const unhex = (s) => [1, 3, 5].map((i) => parseInt(s.substr(i, 2), 16) / 255);
const scaled = (rgb, s) => rgb.map((v) => v * s);
const largest = (...rgbs) => Math.max(...rgbs.flat());

// Colours and density: sigma_s = density * scattering colour, sigma_a = density * absorption
// colour, density the largest coefficient (so both colours stay within [0, 1]).
function colourForm(m) {
  const density = largest(m.sigma_s, m.sigma_a);
  const d = density > 0 ? density : 1;
  return { density, scatter: scaled(m.sigma_s, 1 / d), absorb: scaled(m.sigma_a, 1 / d) };
}
function emissionForm(m) {
  const strength = largest(m.emission);
  return { strength, colour: strength > 0 ? scaled(m.emission, 1 / strength) : [1, 1, 1] };
}

function showError(message) { $('error').textContent = message || ''; }

async function post(path, body) {
  // Declared JSON: the server takes no other body (a type no other page can send unasked).
  const response = await fetch(path, {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: body === undefined ? '{}' : JSON.stringify(body),
  });
  const reply = await response.json();
  if (!response.ok) throw new Error(reply.error || response.statusText);
  return reply;
}

// Sends one patch at a time; patches made meanwhile are merged and sent next.
function change(patch) {
  if (sending) {
    queued = mergePatch(queued || {}, patch);
    return;
  }
  sending = true;
  post('/settings', patch)
    .then((reply) => { settings = reply.settings; generation = reply.generation; showError(''); })
    .catch((e) => showError(e.message))
    .finally(() => {
      sending = false;
      showControls();  // the good settings, also after an error
      if (queued) { const next = queued; queued = null; change(next); }
    });
}
function mergePatch(a, b) {
  const out = { ...a };
  for (const [key, value] of Object.entries(b)) {
    if (key === 'media') {
      out.media = [...(a.media || [])];
      value.forEach((m, i) => { out.media[i] = { ...(out.media[i] || {}), ...m }; });
    } else if (value && typeof value === 'object' && !Array.isArray(value)) {
      out[key] = { ...(a[key] || {}), ...value };
    } else {
      out[key] = value;
    }
  }
  return out;
}
const mediumPatch = (i, m) => ({ media: Array.from({ length: i + 1 }, (_, j) => (j === i ? m : {})) });
const number = (input) => Number(input.value === '' ? NaN : input.value);

function setValue(input, value) {
  if (document.activeElement !== input) input.value = value;
}

function buildMedia() {
  const box = $('media');
  box.textContent = '';
  settings.media.forEach((_, i) => {
    const f = $('medium-template').content.firstElementChild.cloneNode(true);
    f.dataset.index = i;
    f.querySelector('legend').textContent = 'Medium ' + i;
    const q = (c) => f.querySelector('.' + c);
    const all = (c) => [...f.querySelectorAll('.' + c)];
    const m = () => settings.media[i];
    q('mode').addEventListener('change', () => f.classList.toggle('sigma', q('mode').value === 'sigma'));
    q('scatter-colour').addEventListener('change', () => change(mediumPatch(i, { sigma_s: scaled(unhex(q('scatter-colour').value), colourForm(m()).density) })));
    q('absorb-colour').addEventListener('change', () => change(mediumPatch(i, { sigma_a: scaled(unhex(q('absorb-colour').value), colourForm(m()).density) })));
    q('density').addEventListener('change', () => {
      const c = colourForm(m()), d = number(q('density'));
      change(mediumPatch(i, { sigma_s: scaled(c.scatter, d), sigma_a: scaled(c.absorb, d) }));
    });
    for (const key of ['sigma_a', 'sigma_s'])
      all(key).forEach((input) => input.addEventListener('change', () => change(mediumPatch(i, { [key]: all(key).map(number) }))));
    q('g-slider').addEventListener('input', () => change(mediumPatch(i, { g: number(q('g-slider')) })));
    q('g').addEventListener('change', () => change(mediumPatch(i, { g: number(q('g')) })));
    q('scale-slider').addEventListener('input', () => change(mediumPatch(i, { scale: number(q('scale-slider')) })));
    q('scale').addEventListener('change', () => change(mediumPatch(i, { scale: number(q('scale')) })));
    q('emission-colour').addEventListener('change', () =>
      change(mediumPatch(i, { emission: scaled(unhex(q('emission-colour').value), emissionForm(m()).strength) })));
    q('emission-strength').addEventListener('change', () =>
      change(mediumPatch(i, { emission: scaled(emissionForm(m()).colour, number(q('emission-strength'))) })));
    box.appendChild(f);
  });
}

function showControls() {
  const integ = settings.integrator;
  document.querySelectorAll('[data-key]').forEach((input) => setValue(input, integ[input.dataset.key] ?? ''));
  const fixed = integ.radius !== undefined;
  setValue($('lookup'), fixed ? 'radius' : 'k');
  $('k-label').hidden = fixed;
  $('radius-label').hidden = !fixed;
  setValue($('resolution-scale'), String(settings.resolution_scale));
  if ($('media').children.length !== settings.media.length) buildMedia();
  settings.media.forEach((m, i) => {
    const f = $('media').children[i];
    const q = (c) => f.querySelector('.' + c);
    const c = colourForm(m), e = emissionForm(m);
    setValue(q('scatter-colour'), hex(c.scatter));
    setValue(q('absorb-colour'), hex(c.absorb));
    setValue(q('density'), +c.density.toPrecision(6));
    for (const key of ['sigma_a', 'sigma_s']) f.querySelectorAll('.' + key).forEach((input, k) => setValue(input, m[key][k]));
    setValue(q('g-slider'), m.g);
    setValue(q('g'), m.g);
    setValue(q('scale-slider'), m.scale);
    setValue(q('scale'), m.scale);
    setValue(q('emission-colour'), hex(e.colour));
    setValue(q('emission-strength'), +e.strength.toPrecision(6));
  });
}

function showImage(image) {
  if (!image) return;
  $('progress').textContent = (image.passes === 0 ? 'quick look at a quarter size' : 'pass ' + image.passes) +
    ' · ' + image.seconds.toFixed(2) + ' s · ' + image.width + '×' + image.height;
  $('progress').dataset.passes = image.passes;
  $('progress').dataset.generation = image.generation;
  const query = 'exposure=' + $('exposure').value + '&v=' + image.version;
  if (query === shownImage || imageLoading) return;
  imageLoading = true;
  const img = new Image();
  img.onload = () => { $('image').src = img.src; shownImage = query; imageLoading = false; };
  img.onerror = () => { imageLoading = false; };
  img.src = '/image.png?' + query;
}

async function poll() {
  try {
    const state = await (await fetch('/state')).json();
    // Another tab's change: show its settings (unless one of ours is on its way).
    if (!sending && state.generation !== generation) {
      settings = state.settings;
      generation = state.generation;
      showControls();
      showError('');  // an error from before that change is stale
    }
    showImage(state.image);
    if (state.render_error) showError(state.render_error);
  } catch (e) {
    showError('the preview server does not answer: ' + e.message);
  }
  setTimeout(poll, 150);
}

document.querySelectorAll('[data-key]').forEach((input) =>
  input.addEventListener('change', () => {
    const key = input.dataset.key;
    change({ integrator: { [key]: input.type === 'number' ? number(input) : input.value } });
  }));
$('lookup').addEventListener('change', () => {
  // The server forgets "radius" on null (merge patch) and uses k again.
  change({ integrator: { radius: $('lookup').value === 'radius' ? (settings.integrator.radius ?? 0.05) : null } });
});
$('resolution-scale').addEventListener('change', () => change({ resolution_scale: Number($('resolution-scale').value) }));
$('exposure').addEventListener('input', () => { $('exposure-value').textContent = $('exposure').value; });
$('save-scene').addEventListener('click', () =>
  post('/save/scene').then((r) => { $('saved').textContent = 'saved ' + r.scene; showError(''); }).catch((e) => showError(e.message)));
$('save-image').addEventListener('click', () =>
  post('/save/image', { exposure: Number($('exposure').value) })
    .then((r) => { $('saved').textContent = 'saved ' + r.exr + ' and ' + r.png + ' (' + r.passes + ' passes)'; showError(''); })
    .catch((e) => showError(e.message)));
poll();
