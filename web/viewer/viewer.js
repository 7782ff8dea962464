// qmc viewer: opens a .qmc by URL (?url=... or the form) or by drag and drop,
// shows it shaded while it streams in, level by level for a progressive file
// (spec 12), with bytes received, level, vertex and face counts and decode
// time; the slider shows any level decoded so far. Geometry images (13) are
// shown as their 13.9 mesh. window.qmcViewer exposes the state for tests.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

import { QMCLoader } from '../src/QMCLoader.js';

const view = document.getElementById('view');
const status = document.getElementById('status');
const slider = document.getElementById('level');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242a);
scene.add(new THREE.HemisphereLight(0xffffff, 0x404050, 1.2));
const light = new THREE.DirectionalLight(0xffffff, 2.0);
light.position.set(1, 2, 3);
scene.add(light);
const camera = new THREE.PerspectiveCamera(40, 1, 0.001, 1000);
const controls = new OrbitControls(camera, renderer.domElement);
controls.addEventListener('change', render);
const material = new THREE.MeshStandardMaterial({ color: 0xc8b89a, flatShading: true, side: THREE.DoubleSide });
const mesh = new THREE.Mesh(new THREE.BufferGeometry(), material);
scene.add(mesh);
const loader = new QMCLoader().preload();

// What a test reads: every level shown so far, and the load's outcome.
const state = { url: null, levels: [], shown: null, total: 0, received: 0, done: false, error: null,
                onLevelShown: null, decoderReady: false };
window.qmcViewer = state;
loader.ready.then(() => { state.decoderReady = true; });

function render() {
  renderer.render(scene, camera);
}

function resize() {
  renderer.setSize(view.clientWidth, view.clientHeight);
  camera.aspect = view.clientWidth / Math.max(1, view.clientHeight);
  camera.updateProjectionMatrix();
  render();
}

// Framed on the first geometry only, so that levels can be compared.
function frame(geometry) {
  geometry.computeBoundingSphere();
  const { center, radius } = geometry.boundingSphere;
  const r = radius > 0 ? radius : 1;
  camera.position.copy(center).add(new THREE.Vector3(0.6, 0.5, 1).normalize().multiplyScalar(3 * r));
  camera.near = r / 100;
  camera.far = r * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(center);
  controls.update();
}

function describe() {
  const g = state.shown?.userData;
  const name = state.url ? state.url.split('/').pop() : 'no file';
  const lines = [`${name}: ${state.received} of ${state.total || '?'} bytes received`];
  if (g) {
    const level = g.levelCount > 0 ? `level ${g.level} of ${g.levelCount}` : 'single mesh';
    const planes = g.attributes.length ? `, ${g.attributes.length} attribute planes` : '';
    lines.push(`${level}: ${g.vertexCount} vertices, ${g.faceCount} faces${planes}; decode ${g.decodeMs.toFixed(1)} ms`);
  }
  if (state.error) lines.push(`error: ${state.error}`);
  else if (state.done) lines.push('complete');
  status.textContent = lines.join('\n');
}

function show(geometry) {
  if (!state.shown) frame(geometry);
  state.shown = geometry;
  mesh.geometry = geometry;
  document.getElementById('level-value').textContent = geometry.userData.levelCount > 0 ? geometry.userData.level : '-';
  describe();
  render();
}

// Geometries are shown one after another, each until its frame is drawn and
// a test's hook (onLevelShown) has returned.
let queue = Promise.resolve();
async function showUntilDrawn(geometry) {
  show(geometry);
  await new Promise((resolve) => requestAnimationFrame(resolve));
  await state.onLevelShown?.(geometry.userData);
}

function showLevel(geometry) {
  queue = queue.then(() => {
    state.levels.push(geometry);
    slider.max = String(state.levels.length - 1);
    slider.value = slider.max;
    slider.disabled = state.levels.length < 2;
    return showUntilDrawn(geometry);
  });
}

function open(source, name) {
  Object.assign(state, { url: name, levels: [], shown: null, total: 0, received: 0, done: false, error: null });
  slider.disabled = true;
  const onProgress = (event) => {
    state.received = event.loaded;
    state.total = event.total;
    if (event.geometry) showLevel(event.geometry);
    describe();
  };
  const onLoad = (geometry) => {
    queue = queue.then(async () => {
      if (state.levels.length === 0) await showUntilDrawn(geometry); // progressive files: shown level by level
      state.done = true;
      describe();
    });
  };
  const onError = (error) => {
    state.error = error.message;
    describe();
  };
  if (typeof source === 'string') {
    loader.load(source, onLoad, onProgress, onError);
  } else {
    state.received = state.total = source.byteLength;
    loader.parse(source, onLoad, onError, onProgress);
  }
}

slider.addEventListener('input', () => show(state.levels[Number(slider.value)]));
document.getElementById('open').addEventListener('submit', (event) => {
  event.preventDefault();
  const url = document.getElementById('url').value.trim();
  if (url) open(url, url);
});
document.body.addEventListener('dragover', (event) => {
  event.preventDefault();
  document.body.classList.add('dragging');
});
document.body.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
document.body.addEventListener('drop', async (event) => {
  event.preventDefault();
  document.body.classList.remove('dragging');
  const file = event.dataTransfer.files[0];
  if (file) open(await file.arrayBuffer(), file.name);
});
window.addEventListener('resize', resize);
resize();
// The material's shaders compiled now, not when the first mesh arrives.
mesh.geometry = new THREE.TetrahedronGeometry(1e-6);
renderer.compile(scene, camera);
render();
mesh.geometry = new THREE.BufferGeometry();
render();
const initial = new URLSearchParams(location.search).get('url');
if (initial) {
  document.getElementById('url').value = initial;
  open(initial, initial);
}
