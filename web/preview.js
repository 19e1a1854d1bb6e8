'use strict';
// tetglow preview: polls /state, shows the newest image, and sends every change (media, lights,
// camera, integrator) as a JSON merge patch on the settings (POST /settings). Each value typed is checked here first, in the words of
// its field (what was typed, the range allowed); the server checks again. Errors are kept per
// field, all shown at once, each until its field takes a good value; the render goes on with the
// last good settings.
const $ = (id) => document.getElementById(id);
let settings = null;      // the last good settings, as the server holds them
let generation = -1;      // which of them the controls show
let shownImage = '', imageLoading = false;  // shownImage: the version and exposure on screen
let sending = false, queued = null;
let mediumNames = [];     // the scene's names of its media
let lightNames = [];      // and of its lights ("spot", "environment")
let askedCamera = null;   // the view last asked for, until the server holds it (drags and wheel build on it)

// Colours are linear [0, 1] values, shown as the sRGB #rrggbb a screen shows them by.
const encode = (v) => (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055);
const decode = (c) => (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4));
const hex = (rgb) => '#' + rgb.map((v) => Math.round(255 * encode(Math.min(1, Math.max(0, v)))).toString(16).padStart(2, '0')).join('');
const unhex = (s) => [1, 3, 5].map((i) => decode(parseInt(s.substr(i, 2), 16) / 255));
const scaled = (rgb, s) => rgb.map((v) => v * s);
const largest = (...rgbs) => Math.max(...rgbs.flat());

// Colours and density: sigma_s = density * scattering colour, sigma_a = density * absorption
// colour, density the largest coefficient (so both colours stay within [0, 1]).
function colourForm(m) {
  const density = largest(m.sigma_s, m.sigma_a);
  const d = density > 0 ? density : 1;
  return { density, scatter: scaled(m.sigma_s, 1 / d), absorb: scaled(m.sigma_a, 1 / d) };
}
// An emitted colour as its largest channel (the strength) and that colour divided by it.
const rgbOf = (v) => (Array.isArray(v) ? v : [v, v, v]);
function strengthForm(value) {
  const rgb = rgbOf(value), strength = largest(rgb);
  return { strength, colour: strength > 0 ? scaled(rgb, 1 / strength) : [1, 1, 1] };
}
const emissionForm = (m) => strengthForm(m.emission);

// What each field takes (the scene loader's ranges): lo, hi, whether the ends are excluded, integers only.
const kLargest = 3.40282e38;  // colours and scales are floats
const RANGES = {
  spp: { lo: 1, hi: 2 ** 20, integer: true }, photons: { lo: 1, hi: 2 ** 40, integer: true },
  k: { lo: 1, hi: 100000, integer: true }, radius: { lo: 0, hi: kLargest, loOpen: true },
  max_depth: { lo: 1, hi: 2 ** 20, integer: true }, g: { lo: -1, hi: 1, loOpen: true, hiOpen: true },
  position: { lo: -1e12, hi: 1e12 }, look_at: { lo: -1e12, hi: 1e12 }, fov: { lo: 0, hi: 180, loOpen: true, hiOpen: true },
};
const rangeOf = (input) => RANGES[input.dataset.key || input.className] || { lo: 0, hi: kLargest };
function rangeText(r) {
  return (r.integer ? 'an integer ' : 'a number ') + (r.loOpen ? '(' : '[') + r.lo + ', ' + r.hi + (r.hiOpen ? ')' : ']');
}
// The number typed into `input`, or why not in the user's words: "photons per pass: -5 is
// outside the range allowed, an integer [1, 1099511627776]".
function typed(input) {
  const r = rangeOf(input), text = input.value.trim(), x = Number(text);
  const what = input.validity.badInput || text === '' ? 'what was typed' : text;
  let why = '';
  if (input.validity.badInput || text === '' || !Number.isFinite(x)) why = ' is not a number';
  else if (x < r.lo || x > r.hi || (r.loOpen && x === r.lo) || (r.hiOpen && x === r.hi) || (r.integer && !Number.isInteger(x)))
    why = ' is outside the range allowed';
  return why ? { error: input.dataset.label + ': ' + what + why + ', ' + rangeText(r) } : { value: x };
}

const errors = new Map();  // field -> its message; 'render': the render's own
function setError(field, message) {
  if ((errors.get(field) || '') === (message || '')) return;
  if (message) errors.set(field, message);
  else errors.delete(field);
  const list = $('error');
  list.textContent = '';
  for (const [key, text] of errors) {
    const item = document.createElement('li');
    item.dataset.field = key;
    item.textContent = text;
    list.appendChild(item);
  }
}

async function post(path, body) {
  // Declared JSON: the server takes no other body (a type no other page can send unasked).
  const response = await fetch(path, {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: body === undefined ? '{}' : JSON.stringify(body),
  });
  const reply = await response.json();
  if (!response.ok) throw new Error(reply.error || response.statusText);
  return reply;
}

// Sends one patch at a time; patches made meanwhile are merged and sent next. `fields`: the
// fields the patch comes from, whose errors it clears or sets ("<label> <typed>: <the server's error>").
let queuedFields = {};
function change(patch, fields = {}) {
  if (sending) {
    queued = mergePatch(queued || {}, patch);
    Object.assign(queuedFields, fields);
    return;
  }
  sending = true;
  post('/settings', patch)
    .then((reply) => {
      settings = reply.settings;
      generation = reply.generation;
      for (const field of Object.keys(fields)) setError(field, '');
    })
    .catch((e) => { for (const [field, words] of Object.entries(fields)) setError(field, words + ': ' + e.message); })
    .finally(() => {
      sending = false;
      if (!queued) askedCamera = null;
      showControls();  // the good settings, also after an error
      if (queued) {
        const next = queued, nextFields = queuedFields;
        queued = null;
        queuedFields = {};
        change(next, nextFields);
      }
    });
}
// A number field: checked here, then sent as the patch makePatch(value) builds.
function onNumber(input, field, makePatch) {
  input.addEventListener('change', () => {
    const t = typed(input);
    if (t.error) {
      setError(field, t.error);
      showControls();
      return;
    }
    change(makePatch(t.value), { [field]: input.dataset.label + ' ' + input.value });
  });
}
// A colour picker or a select: sent as the patch makePatch(value) builds, its error shown as
// "<words> <value>: <the server's error>" until it takes a good value.
function onChoice(input, field, words, makePatch) {
  input.addEventListener('change', () => change(makePatch(input.value), { [field]: words + ' ' + input.value }));
}
function mergePatch(a, b) {
  const out = { ...a };
  for (const [key, value] of Object.entries(b)) {
    if (key === 'media' || key === 'lights') {
      out[key] = [...(a[key] || [])];
      value.forEach((m, i) => { out[key][i] = { ...(out[key][i] || {}), ...m }; });
    } else if (value && typeof value === 'object' && !Array.isArray(value)) {
      out[key] = { ...(a[key] || {}), ...value };
    } else {
      out[key] = value;
    }
  }
  return out;
}
const entryPatch = (key, i, m) => ({ [key]: Array.from({ length: i + 1 }, (_, j) => (j === i ? m : {})) });
const mediumPatch = (i, m) => entryPatch('media', i, m);
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
    f.querySelector('legend').textContent = mediumNames[i] || 'Medium ' + i;
    const q = (c) => f.querySelector('.' + c);
    const all = (c) => [...f.querySelectorAll('.' + c)];
    const m = () => settings.media[i];
    q('mode').addEventListener('change', () => f.classList.toggle('sigma', q('mode').value === 'sigma'));
    const name = (c) => f.querySelector('legend').textContent + ' · ' + c;
    for (const input of f.querySelectorAll('input[type=number]')) input.dataset.label = name(input.dataset.label);
    const field = (c) => 'media/' + i + '/' + c;
    onChoice(q('scatter-colour'), field('scatter-colour'), name('scattering colour'),
      (v) => mediumPatch(i, { sigma_s: scaled(unhex(v), colourForm(m()).density) }));
    onChoice(q('absorb-colour'), field('absorb-colour'), name('absorption colour'),
      (v) => mediumPatch(i, { sigma_a: scaled(unhex(v), colourForm(m()).density) }));
    onNumber(q('density'), field('density'), (d) => {
      const c = colourForm(m());
      return mediumPatch(i, { sigma_s: scaled(c.scatter, d), sigma_a: scaled(c.absorb, d) });
    });
    for (const key of ['sigma_a', 'sigma_s'])
      all(key).forEach((input, k) => onNumber(input, field(key + k), (x) => mediumPatch(i, { [key]: m()[key].map((v, j) => (j === k ? x : v)) })));
    q('g-slider').addEventListener('input', () => change(mediumPatch(i, { g: number(q('g-slider')) }), { [field('g')]: name('g') + ' ' + q('g-slider').value }));
    onNumber(q('g'), field('g'), (g) => mediumPatch(i, { g }));
    q('scale-slider').addEventListener('input', () =>
      change(mediumPatch(i, { scale: number(q('scale-slider')) }), { [field('scale')]: name('density scale') + ' ' + q('scale-slider').value }));
    onNumber(q('scale'), field('scale'), (scale) => mediumPatch(i, { scale }));
    onChoice(q('emission-colour'), field('emission-colour'), name('emission colour'),
      (v) => mediumPatch(i, { emission: scaled(unhex(v), emissionForm(m()).strength) }));
    onNumber(q('emission-strength'), field('emission'), (x) => mediumPatch(i, { emission: scaled(emissionForm(m()).colour, x) }));
    box.appendChild(f);
  });
}

// What each light's emitted quantity is, by its key in the scene file.
const EMITTED = {
  intensity: 'radiant intensity, power per unit solid angle: its largest channel (times the scale)',
  irradiance: 'irradiance on a surface facing the light, power per unit area: its largest channel (times the scale)',
  radiance: 'emitted radiance, power per unit area and solid angle: its largest channel (times the scale)',
};
const emittedKey = (light) => Object.keys(EMITTED).find((k) => k in light);

function buildLights() {
  const box = $('lights');
  box.textContent = '';
  settings.lights.forEach((light, i) => {
    const f = $('light-template').content.firstElementChild.cloneNode(true);
    const q = (c) => f.querySelector('.' + c);
    const key = emittedKey(light), name = lightNames[i] || 'light ' + i, now = () => settings.lights[i];
    const field = (c) => 'lights/' + i + '/' + c;
    f.querySelector('legend').textContent = 'Light · ' + name;
    const label = f.querySelector('.strength-label');
    label.firstChild.textContent = key + ' ';
    label.title = EMITTED[key];
    q('strength').dataset.label = name + ' · ' + key;
    q('scale').dataset.label = name + ' · scale';
    q('on').addEventListener('change', () => change(entryPatch('lights', i, { on: q('on').checked }), { [field('on')]: name + ' · on ' + q('on').checked }));
    onChoice(q('light-colour'), field('colour'), name + ' · colour',
      (v) => entryPatch('lights', i, { [key]: scaled(unhex(v), strengthForm(now()[key]).strength) }));
    onNumber(q('strength'), field(key), (x) => entryPatch('lights', i, { [key]: scaled(strengthForm(now()[key]).colour, x) }));
    onNumber(q('scale'), field('scale'), (scale) => entryPatch('lights', i, { scale }));
    box.appendChild(f);
  });
}

// The camera: orbit about the look-at point (around the up direction), pan across the view,
// zoom towards the look-at point. Each builds on the view last asked for.
const add = (a, b) => a.map((x, i) => x + b[i]);
const sub = (a, b) => a.map((x, i) => x - b[i]);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => scaled(a, 1 / Math.hypot(...a));
const clamp = (x, lo, hi) => Math.min(hi, Math.max(lo, x));
const viewCamera = () => ({ ...settings.camera, ...(askedCamera || {}) });
const kRadiansPerPixel = 0.01, kPole = 0.02;  // the view stays this far (radians) from the up direction

function orbit(cam, dx, dy) {
  const up = unit(cam.up), offset = sub(cam.position, cam.look_at), r = Math.hypot(...offset);
  const across = sub(offset, scaled(up, dot(offset, up)));
  const e1 = Math.hypot(...across) > 1e-9 * r ? unit(across) : unit(cross(up, Math.abs(up[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
  const e2 = cross(up, e1);
  const polar = clamp(Math.acos(clamp(dot(offset, up) / r, -1, 1)) - dy * kRadiansPerPixel, kPole, Math.PI - kPole);
  const turn = -dx * kRadiansPerPixel;
  const around = add(scaled(e1, Math.cos(turn)), scaled(e2, Math.sin(turn)));
  return { position: add(cam.look_at, scaled(add(scaled(around, Math.sin(polar)), scaled(up, Math.cos(polar))), r)), look_at: cam.look_at };
}
function pan(cam, dx, dy) {
  const view = sub(cam.look_at, cam.position);
  const right = unit(cross(view, cam.up)), up = unit(cross(right, view));
  // A pixel's width at the look-at point: the image follows the drag there.
  const perPixel = (2 * Math.hypot(...view) * Math.tan((cam.fov * Math.PI) / 360)) / $('image').clientHeight;
  const move = add(scaled(right, -dx * perPixel), scaled(up, dy * perPixel));
  return { position: add(cam.position, move), look_at: add(cam.look_at, move) };
}
function zoom(cam, wheel) {
  const offset = sub(cam.position, cam.look_at), r = Math.hypot(...offset);
  const k = Math.max(Math.exp(wheel * 0.001), 1e-6 / r);
  return { position: add(cam.look_at, scaled(offset, k)), look_at: cam.look_at };
}
function moveCamera(view) {
  askedCamera = view;
  change({ camera: view }, { camera: 'camera' });
}
let drag = null;  // the pointer's start and the view then
$('image').addEventListener('pointerdown', (e) => {
  if (!settings || e.button !== 0) return;
  e.preventDefault();
  $('image').setPointerCapture(e.pointerId);
  drag = { x: e.clientX, y: e.clientY, view: viewCamera(), pan: e.shiftKey };
});
$('image').addEventListener('pointermove', (e) => {
  if (!drag) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (dx || dy) moveCamera((drag.pan ? pan : orbit)(drag.view, dx, dy));
});
for (const end of ['pointerup', 'pointercancel']) $('image').addEventListener(end, () => { drag = null; });
$('image').addEventListener('wheel', (e) => {
  e.preventDefault();
  if (settings) moveCamera(zoom(viewCamera(), e.deltaY));
}, { passive: false });
for (const key of ['position', 'look_at'])
  $('camera').querySelectorAll('.' + key).forEach((input, k) =>
    onNumber(input, 'camera/' + key + k, (x) => ({ camera: { [key]: viewCamera()[key].map((v, j) => (j === k ? x : v)) } })));
onNumber($('camera').querySelector('.fov'), 'camera/fov', (fov) => ({ camera: { fov } }));

function showControls() {
  const integ = settings.integrator;
  document.querySelectorAll('[data-key]').forEach((input) => setValue(input, integ[input.dataset.key] ?? ''));
  const fixed = integ.radius !== undefined;
  setValue($('lookup'), fixed ? 'radius' : 'k');
  $('k-label').hidden = fixed;
  $('radius-label').hidden = !fixed;
  setValue($('resolution-scale'), String(settings.resolution_scale));
  for (const key of ['position', 'look_at'])
    $('camera').querySelectorAll('.' + key).forEach((input, k) => setValue(input, +settings.camera[key][k].toPrecision(6)));
  setValue($('camera').querySelector('.fov'), settings.camera.fov);
  if ($('lights').children.length !== settings.lights.length) buildLights();
  settings.lights.forEach((light, i) => {
    const f = $('lights').children[i], key = emittedKey(light), e = strengthForm(light[key]);
    f.querySelector('.on').checked = light.on;
    setValue(f.querySelector('.light-colour'), hex(e.colour));
    setValue(f.querySelector('.strength'), +e.strength.toPrecision(6));
    setValue(f.querySelector('.scale'), light.scale);
  });
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
    mediumNames = state.media_names || [];
    lightNames = state.light_names || [];
    if (!sending && state.generation !== generation) {
      settings = state.settings;
      generation = state.generation;
      showControls();
    }
    showImage(state.image);
    setError('render', state.render_error);
    setError('warnings', (state.warnings || []).map((w) => 'warning: ' + w).join(' '));
    setError('server', '');
  } catch (e) {
    setError('server', 'the preview server does not answer: ' + e.message);
  }
  setTimeout(poll, 150);
}

document.querySelectorAll('[data-key]').forEach((input) => {
  const key = input.dataset.key;
  if (input.type === 'number') onNumber(input, 'integrator/' + key, (x) => ({ integrator: { [key]: x } }));
  else onChoice(input, 'integrator/' + key, input.dataset.label, (v) => ({ integrator: { [key]: v } }));
});
// The server forgets "radius" on null (merge patch) and uses k again.
onChoice($('lookup'), 'integrator/lookup', 'lookup',
  (v) => ({ integrator: { radius: v === 'radius' ? (settings.integrator.radius ?? 0.05) : null } }));
onChoice($('resolution-scale'), 'resolution_scale', 'resolution scale', (v) => ({ resolution_scale: Number(v) }));
$('exposure').addEventListener('input', () => { $('exposure-value').textContent = $('exposure').value; });
const saveScene = (body) =>
  post('/save/scene', body).then((r) => { $('saved').textContent = 'saved ' + r.scene; setError('save', ''); }).catch((e) => setError('save', e.message));
$('save-scene').addEventListener('click', () => saveScene({}));
$('save-over').addEventListener('click', () => { if (window.confirm('Write the changed values into the scene file itself?')) saveScene({ overwrite: true }); });
$('save-image').addEventListener('click', () =>
  post('/save/image', { exposure: Number($('exposure').value) })
    .then((r) => { $('saved').textContent = 'saved ' + r.exr + ' and ' + r.png + ' (' + r.passes + ' passes)'; setError('save', ''); })
    .catch((e) => setError('save', e.message)));
poll();
