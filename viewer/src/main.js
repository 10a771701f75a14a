// The replay viewer's entry point: reads window.PROXSIM_DATA (written by the
// report into data.js), builds the page, and replays the run: robot, rays,
// profile, terrain map and distance curves all show the same time t. Exposes
// window.proxsimViewer for tests.
import * as THREE from 'three';
import uplotCss from 'uplot/dist/uPlot.min.css';
import viewerCss from './viewer.css';
import { ControlsPanel } from './controls_panel.js';
import { CurvesView } from './curves_view.js';
import { ProfileView } from './profile_view.js';
import { RaysView } from './rays_view.js';
import { ZonesView } from './zones_view.js';
import { RobotView } from './robot_view.js';
import { SceneView } from './scene_view.js';
import { TerrainView } from './terrain_view.js';
import { timeSpan, timeStep } from './timeline.js';
import { WalkView } from './walk_view.js';

function injectCss(text) {
  const style = document.createElement('style');
  style.textContent = text;
  document.head.appendChild(style);
}

function div(cls, parent) {
  const d = document.createElement('div');
  d.className = cls;
  parent.appendChild(d);
  return d;
}

/** Where to look first: just ahead of the robot, or at the sensors and objects. */
function initialView(data, robot, bounds) {
  const root = robot.rootLink();
  if (root) {
    const p = root.position;
    return [new THREE.Vector3(p.x + 1.0, p.y, 0.45), 4.2];
  }
  const box = bounds.clone();
  for (const s of data.sensors) {
    if (s.origin.length >= 3) box.expandByPoint(new THREE.Vector3(s.origin[0], s.origin[1], s.origin[2]));
  }
  if (box.isEmpty()) return [new THREE.Vector3(0, 0, 0.5), 4];
  const size = box.getSize(new THREE.Vector3()).length();
  return [box.getCenter(new THREE.Vector3()), Math.max(1.4 * size, 1.5)];
}

function start() {
  const data = window.PROXSIM_DATA;
  const root = document.getElementById('proxsim-viewer') || document.body;
  if (!data) {
    root.innerHTML = '<p class="proxsim-error">No run data: data.js did not load (keep it beside index.html).</p>';
    throw new Error('proxsim viewer: window.PROXSIM_DATA is missing');
  }
  injectCss(uplotCss);
  injectCss(viewerCss);

  // page: bar, 3D view with its side panel, curves
  const app = div('proxsim-app', root);
  const bar = div('proxsim-bar', app);
  const title = document.createElement('h1');
  title.textContent = 'proxsim replay';
  bar.appendChild(title);
  const main = div('proxsim-main', app);
  const view = div('proxsim-3d', main);
  const side = div('proxsim-side', main);
  const curvesBox = div('proxsim-curves', app);

  const span = timeSpan(data);
  const stage = new SceneView(view);
  const bounds = stage.addObjects(data.scene.objects || []);
  const robot = new RobotView(stage.scene, data.scene.robot, data.poses);
  const rays = new RaysView(stage.scene, data.sensors, data.statusColors);
  const profile = new ProfileView(stage.scene, data.profile, data.sensors, data.objectColors);
  const zones = new ZonesView(stage.scene, data.zones, data.sensors);
  const terrain = new TerrainView(stage.scene, data.terrain);
  const rootLink = robot.rootLink();
  const walk = new WalkView(stage.scene, data.poses, rootLink ? rootLink.name : null, data.events, data.collisions, data.fall);
  robot.markCollisions(data.collisions);
  rays.resize(stage.size);

  const state = { t: span[0], playing: false, speed: 1, follow: Boolean(data.poses),
    visible: data.sensors.map(() => true), dirty: true };
  const followed = robot.rootLink();
  const lastRoot = new THREE.Vector3();

  // show time t everywhere
  function apply() {
    if (followed) lastRoot.copy(followed.position);
    robot.update(state.t);
    stage.moveObjects(data.objectPoses, state.t);
    if (followed && state.follow) stage.translate(followed.position.clone().sub(lastRoot));
    rays.update(state.t, state.visible);
    profile.update(state.t, state.visible);
    zones.update(state.t, state.visible);
    terrain.update(state.t);
    walk.update(state.t);
    curves.update(state.t);
    panel.show(state.t, state.playing);
    state.dirty = false;
  }
  function setTime(t) {
    state.t = Math.min(Math.max(Number(t), span[0]), span[1]);
    apply();
  }
  function setPlaying(on) {
    if (on && state.t >= span[1]) state.t = span[0];
    state.playing = on;
    state.dirty = true;
  }

  const curves = new CurvesView(curvesBox, data.sensors, setTime);
  const panel = new ControlsPanel(bar, side, data, span, timeStep(data), {
    onPlayToggle: () => setPlaying(!state.playing),
    onSeek: (t) => { setPlaying(false); setTime(t); },
    onSpeed: (x) => { state.speed = x; },
    onFollow: (on) => { state.follow = on; },
    onSensor: (j, on) => { state.visible[j] = on; curves.setSensorVisible(j, on); state.dirty = true; },
    onTerrain: (on) => { terrain.setVisible(on); state.dirty = true; },
  });
  robot.update(state.t);
  const [target, distance] = initialView(data, robot, bounds);
  stage.frame(target, distance);
  apply();

  window.addEventListener('resize', () => { stage.resize(); rays.resize(stage.size); curves.resize(); state.dirty = true; });
  window.addEventListener('keydown', (e) => {
    if (e.code === 'Space' && e.target.tagName !== 'INPUT') { e.preventDefault(); setPlaying(!state.playing); }
  });

  // the replay loop: advance time when playing, render every frame
  let frameCount = 0;
  let last = performance.now();
  function tick(now) {
    const dt = Math.min((now - last) / 1000, 0.1);
    last = now;
    if (state.playing) {
      state.t = Math.min(state.t + dt * state.speed, span[1]);
      if (state.t >= span[1]) state.playing = false;
      state.dirty = true;
    }
    if (state.dirty) apply();
    stage.render();
    frameCount += 1;
    requestAnimationFrame(tick);
  }
  requestAnimationFrame(tick);

  window.proxsimViewer = {
    setTime,
    currentTime: () => state.t,
    robotLinkPosition: (name) => robot.linkPosition(name),
    objectPosition: (name) => stage.objectPosition(name),
    get frameCount() { return frameCount; },
    rayEndpoints: () => rays.endpoints(),
    profilePointsShown: () => profile.shownCount(),
    zonePointsShown: () => zones.pointsShown(),
    eventsShown: () => walk.eventsShown(),
    struckLinks: () => robot.struckLinks(),
    collisionsShown: () => walk.collisionsShown(),
    mapCellsShown: () => terrain.cellsShown(),
    hazardsShown: () => terrain.hazardsShown(),
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    isPlaying: () => state.playing,
    timeSpan: () => span.slice(),
  };
  // a newcomer opens the page and watches: start playing unless #paused
  if (!/paused/.test(window.location.hash)) setPlaying(true);
}

start();
