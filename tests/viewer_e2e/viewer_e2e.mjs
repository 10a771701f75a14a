// End-to-end test of the replay viewer in a real browser (Debian's chromium,
// driven by playwright-core): opens OUT/report/index.html from disk, fails on
// any console or page error, checks that the 3D canvas is drawn, that moving
// the time (slider and API) moves the robot (or, without a robot, changes the
// rays or the profile), that a sensor toggle hides its ray, that the terrain
// map (runs with a robot) grows cell by cell as the run's files say and marks
// its hazards once found, that the curves are drawn, and saves
// OUT/report/screenshot.png. With --climb-m M (a walk over stairs), the robot
// shown climbs: its pelvis rises by at least M over the replay. The screenshot
// is taken at time --shot-at-s T, or else at the fraction --screenshot-at F of
// the replay (default 0.6).
//
//   node tests/viewer_e2e/viewer_e2e.mjs OUT [--viewer-dir viewer] [--screenshot PATH]
//                                        [--climb-m M] [--shot-at-s T | --screenshot-at F]
//
// Exit 0 pass, 1 fail, 77 skip (only when /usr/bin/chromium is missing).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';

const CHROMIUM = '/usr/bin/chromium';
const SKIP = 77;
const here = path.dirname(fileURLToPath(import.meta.url));

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
}

const outDir = process.argv[2];
if (!outDir || outDir.startsWith('--')) {
  console.error('usage: node viewer_e2e.mjs OUT [--viewer-dir DIR] [--screenshot PATH]');
  process.exit(2);
}
const reportDir = path.resolve(outDir, 'report');
const indexHtml = path.join(reportDir, 'index.html');
const screenshotPath = path.resolve(option('--screenshot', path.join(reportDir, 'screenshot.png')));
const screenshotAt = Number(option('--screenshot-at', '0.6'));
if (!fs.existsSync(CHROMIUM)) {
  console.log(`viewer_e2e: SKIP: ${CHROMIUM} is missing (scripts/install-deps.sh browser installs it)`);
  process.exit(SKIP);
}
if (!fs.existsSync(indexHtml)) {
  console.error(`viewer_e2e: ${indexHtml} does not exist (run make_report.py first)`);
  process.exit(1);
}
// playwright-core lives in the viewer's node_modules
const viewerDir = path.resolve(option('--viewer-dir', path.join(here, '..', '..', 'viewer')));
const { chromium } = createRequire(path.join(viewerDir, 'package.json'))('playwright-core');

let passed = 0;
const failures = [];
function check(ok, what) {
  if (ok) { passed += 1; console.log(`  ok   ${what}`); } else { failures.push(what); console.log(`  FAIL ${what}`); }
}

const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'proxsim-e2e-'));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: CHROMIUM,
  headless: true,
  args: ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  viewport: { width: 1200, height: 760 },
});
const errors = [];
try {
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
  await page.goto(pathToFileURL(indexHtml).href);
  await page.waitForFunction(() => window.proxsimViewer && window.proxsimViewer.frameCount > 5, null, { timeout: 20000 });

  // it plays on opening
  const t0 = await page.evaluate(() => window.proxsimViewer.currentTime());
  await page.waitForFunction((t) => window.proxsimViewer.currentTime() > t, t0, { timeout: 5000 }).catch(() => {});
  check(await page.evaluate((t) => window.proxsimViewer.currentTime() > t, t0), 'the replay plays on opening');
  const fps = await page.evaluate(() => new Promise((resolve) => {
    const f0 = window.proxsimViewer.frameCount;
    setTimeout(() => resolve((window.proxsimViewer.frameCount - f0) / 2), 2000);
  }));
  console.log(`  info replay at ${fps.toFixed(1)} frames/s (software rendering)`);
  await page.evaluate(() => window.proxsimViewer.pause());

  const info = await page.evaluate(() => ({
    span: window.proxsimViewer.timeSpan(),
    links: window.PROXSIM_DATA.poses ? Object.keys(window.PROXSIM_DATA.poses.links) : [],
  }));
  const [tStart, tEnd] = info.span;
  // the state shown at a time: link positions, rays, profile points
  const stateAt = (t) => page.evaluate(([tt, links]) => {
    const v = window.proxsimViewer;
    if (tt !== null) v.setTime(tt);
    return { t: v.currentTime(), links: links.map((n) => v.robotLinkPosition(n)),
      rays: v.rayEndpoints(), points: v.profilePointsShown() };
  }, [t, info.links]);
  const moved = (a, b) => Math.max(0, ...a.links.map((p, i) => Math.hypot(
    p[0] - b.links[i][0], p[1] - b.links[i][1], p[2] - b.links[i][2])));
  const changed = (a, b) => a.points !== b.points || a.rays.some((v, i) => Math.abs(v - b.rays[i]) > 1e-6);

  const early = await stateAt(tStart + 0.1 * (tEnd - tStart));
  const middle = await stateAt(tStart + 0.5 * (tEnd - tStart));
  // the slider: set its value as a user's drag does, with an input event
  const sliderT = tStart + 0.8 * (tEnd - tStart);
  await page.evaluate((t) => {
    const s = document.querySelector('.proxsim-slider');
    s.value = String(t);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, sliderT);
  const late = await stateAt(null);
  check(Math.abs(late.t - sliderT) < 0.05, `the slider sets the time (${late.t.toFixed(2)} s, wanted ${sliderT.toFixed(2)} s)`);
  if (info.links.length) {
    check(moved(early, middle) > 0.05, `setTime moves the robot (${moved(early, middle).toFixed(3)} m)`);
    check(moved(middle, late) > 0.05, `the slider moves the robot (${moved(middle, late).toFixed(3)} m)`);
  } else {
    check(changed(early, late), 'without a robot, moving the time changes the rays or the profile');
  }
  check(late.points >= early.points && late.points > 0, `the profile accumulates (${early.points} → ${late.points} points)`);

  // the strategy's events: a marker and a list row each, shown once their time has come
  const events = await page.evaluate(([a, b]) => {
    const v = window.proxsimViewer;
    const total = (window.PROXSIM_DATA.events || []).length;
    v.setTime(a);
    const atStart = v.eventsShown();
    v.setTime(b);
    return { total, atStart, atEnd: v.eventsShown(), rows: document.querySelectorAll('.proxsim-event').length,
      past: document.querySelectorAll('.proxsim-event-past').length };
  }, [tStart, tEnd]);
  check(events.atEnd === events.total && events.rows === events.total && events.past === events.total,
    `every strategy event is marked and listed by the end (${events.atEnd}/${events.rows}/${events.total})`);
  check(events.total === 0 || events.atStart < events.total, `events appear with time (${events.atStart} at the start)`);

  // collisions (docs/outcomes.md): a red ball at each contact point and the
  // struck link drawn red, from the collision's time on
  const collisions = await page.evaluate(([a, b]) => {
    const v = window.proxsimViewer;
    const list = window.PROXSIM_DATA.collisions || [];
    v.setTime(a);
    const before = { balls: v.collisionsShown(), struck: v.struckLinks() };
    v.setTime(b);
    return { total: list.length, links: list.map((c) => c.link), before, after: { balls: v.collisionsShown(), struck: v.struckLinks() } };
  }, [tStart, tEnd]);
  if (collisions.total > 0) {
    check(collisions.before.balls === 0 && collisions.before.struck.length === 0 || collisions.before.balls < collisions.total,
      `collisions appear with time (${collisions.before.balls} at the start)`);
    check(collisions.after.balls === collisions.total, `every collision point is marked by the end (${collisions.after.balls}/${collisions.total})`);
    check(collisions.links.every((l) => collisions.after.struck.includes(l)),
      `the struck links are drawn red (${collisions.after.struck.join(', ')})`);
  }

  // moving objects (docs/worlds.md): each drawn where objects_poses.csv puts it at the time shown
  const movers = await page.evaluate(([a, b]) => {
    const v = window.proxsimViewer;
    const d = window.PROXSIM_DATA.objectPoses;
    if (!d) return null;
    const name = Object.keys(d.objects)[0];
    const expected = (t) => {
      let i = 0;
      while (i + 1 < d.t.length && d.t[i + 1] <= t) i += 1;
      return d.objects[name].slice(7 * i, 7 * i + 3);
    };
    const at = (t) => { v.setTime(t); return { shown: v.objectPosition(name), want: expected(v.currentTime()) }; };
    return { name, states: [at(a + 0.2 * (b - a)), at(a + 0.7 * (b - a))] };
  }, [tStart, tEnd]);
  if (movers) {
    const off = (s) => Math.hypot(...s.shown.map((x, k) => x - s.want[k]));
    check(movers.states.every((s) => off(s) < 1e-3),
      `${movers.name} is drawn where objects_poses.csv puts it (${movers.states.map((s) => off(s).toFixed(4)).join(', ')} m off)`);
    const [s0, s1] = movers.states;
    check(Math.hypot(...s0.shown.map((x, k) => x - s1.shown[k])) > 0.05, `${movers.name} moves over the replay`);
  }

  // multi-zone sensors: each sample's zones drawn as points (and their grid),
  // as many as the zones with a target in data.js at that sample; none for a
  // sensor toggled off (the toggles are the rays' own, checked above)
  const zones = await page.evaluate(([a, b]) => {
    const v = window.proxsimViewer;
    const list = window.PROXSIM_DATA.zones || [];
    if (list.length === 0) return null;
    const due = (t) => list.reduce((n, z) => {
      if (z.t.length === 0 || t < z.t[0]) return n;
      let i = 0;
      while (i + 1 < z.t.length && z.t[i + 1] <= t) i += 1;
      let count = 0;
      for (let k = 0; k < z.nx * z.ny; k++) if (z.p[3 * (i * z.nx * z.ny + k)] !== null) count += 1;
      return n + count;
    }, 0);
    const states = [];
    for (const f of [0.3, 0.6, 0.9]) {
      v.setTime(a + f * (b - a));
      states.push({ shown: v.zonePointsShown(), due: due(v.currentTime()) });
    }
    return { sensors: list.length, states };
  }, [tStart, tEnd]);
  if (zones) {
    check(zones.states.every((s) => s.shown === s.due) && zones.states.some((s) => s.shown > 0),
      `every zone with a target is drawn (${zones.states.map((s) => `${s.shown}/${s.due}`).join(', ')})`);
  }

  // the terrain map: every run with a robot has one; its cells appear when the
  // files say they were first measured, all of them by the end; its hazards
  // are marked (3D and side panel) once found; its toggle hides the layer
  const map = await page.evaluate(([a, b]) => {
    const v = window.proxsimViewer;
    const d = window.PROXSIM_DATA.terrain;
    if (!d) return null;
    const at = (t) => {
      v.setTime(t);
      return { t: v.currentTime(), cells: v.mapCellsShown(), hazards: v.hazardsShown(),
        rows: document.querySelectorAll('.proxsim-hazard-found').length,
        cellsDue: d.t.filter((x) => x <= v.currentTime()).length,
        hazardsDue: d.hazards.filter((h) => h.t === null || h.t <= v.currentTime()).length };
    };
    const states = [at(a), at(a + 0.25 * (b - a)), at(a + 0.5 * (b - a)), at(a + 0.75 * (b - a)), at(b)];
    document.querySelector('.proxsim-terrain-toggle').click();
    const hidden = v.mapCellsShown() + v.hazardsShown();
    document.querySelector('.proxsim-terrain-toggle').click();
    return { total: d.t.length, hazardTotal: d.hazards.length, states, hidden, shownAgain: v.mapCellsShown() };
  }, [tStart, tEnd]);
  check((map !== null) === (info.links.length > 0),
    `a run with a robot has a terrain map layer, a run without none (${map === null ? 'none' : `${map.total} cells`})`);
  const figure = ['terrain.png', 'terrain.svg'].every((f) => fs.existsSync(path.join(reportDir, f)));
  check(figure === (map !== null), `the report has terrain.png/.svg exactly when the run has a map (${figure})`);
  if (map) {
    const [first, , , , last] = map.states;
    check(map.total > 0 && last.cells === map.total, `by the end every measured cell is drawn (${last.cells}/${map.total})`);
    check(first.cells < map.total, `the map grows with time (${map.states.map((s) => s.cells).join(' → ')} cells)`);
    check(map.states.every((s) => s.cells === s.cellsDue),
      'at each time the cells drawn are those the files say were measured by then');
    check(map.states.every((s) => s.hazards === s.hazardsDue && s.rows === s.hazardsDue) && last.hazards === map.hazardTotal,
      `hazards are marked and listed once found (${map.states.map((s) => s.hazards).join(' → ')} of ${map.hazardTotal})`);
    check(map.hidden === 0 && map.shownAgain === map.total, 'the terrain toggle hides and shows the map');
  }

  // a sensor toggle hides that sensor's ray (its segment collapses to its origin);
  // clicked from the page: playwright's own click waits for steady frames, slow
  // under software rendering
  const toggle = () => page.evaluate(() => document.querySelector('.proxsim-sensor-toggle').click());
  await toggle();
  await page.waitForFunction((f) => window.proxsimViewer.frameCount > f + 1,
    await page.evaluate(() => window.proxsimViewer.frameCount));
  const r = (await stateAt(null)).rays;
  check(r[0] === r[3] && r[1] === r[4] && r[2] === r[5], 'unchecking a sensor hides its ray');
  await toggle();

  // the per-frame update (robot, rays, profile, cursor) is cheap: buffers are
  // rewritten in place, so the frame rate is the renderer's alone
  const updateMs = await page.evaluate(([a, b]) => {
    const v = window.proxsimViewer;
    const n = 300;
    const t0 = performance.now();
    for (let i = 0; i < n; i++) v.setTime(a + ((b - a) * i) / n);
    return (performance.now() - t0) / n;
  }, [tStart, tEnd]);
  check(updateMs < 4, `one time update takes ${updateMs.toFixed(3)} ms (< 4 ms, for >= 30 fps)`);

  // the curves: uPlot's canvas, laid out with a size
  const curve = await page.evaluate(() => {
    const c = document.querySelector('.proxsim-curves .uplot canvas');
    return c ? [c.width, c.height] : null;
  });
  check(curve !== null && curve[0] > 100 && curve[1] > 50, `the distance curves are drawn (${curve})`);

  // a walk over stairs: the robot shown climbs them (its pelvis, sampled over the replay)
  const climbM = Number(option('--climb-m', '0'));
  if (climbM > 0) {
    const rise = await page.evaluate(([a, b]) => {
      const v = window.proxsimViewer;
      let lo = Infinity;
      let hi = -Infinity;
      for (let i = 0; i <= 200; i++) {
        v.setTime(a + ((b - a) * i) / 200);
        const z = v.robotLinkPosition('pelvis')[2];
        lo = Math.min(lo, z);
        hi = Math.max(hi, z);
      }
      return hi - lo;
    }, [tStart, tEnd]);
    check(rise >= climbM, `the robot climbs: its pelvis rises ${rise.toFixed(3)} m over the replay (>= ${climbM} m)`);
  }

  // the 3D canvas is not blank: count the colours of its region in the page's
  // screenshot (which is also the artefact)
  const shotAt = option('--shot-at-s', null);
  await page.evaluate(([t, f]) => {
    const [a, b] = window.proxsimViewer.timeSpan();
    window.proxsimViewer.setTime(t === null ? a + f * (b - a) : Number(t));
  }, [shotAt, screenshotAt]);
  await page.waitForFunction((f) => window.proxsimViewer.frameCount > f + 2,
    await page.evaluate(() => window.proxsimViewer.frameCount));
  fs.mkdirSync(path.dirname(screenshotPath), { recursive: true });
  const shot = await page.screenshot({ path: screenshotPath });
  console.log(`  info screenshot saved to ${screenshotPath}`);
  const box = await page.locator('.proxsim-3d canvas').boundingBox();
  const probe = await context.newPage();
  const colours = await probe.evaluate(async ([b64, r]) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = Math.round(r.width); c.height = Math.round(r.height);
    const g = c.getContext('2d');
    g.drawImage(img, -Math.round(r.x), -Math.round(r.y));
    const px = g.getImageData(0, 0, c.width, c.height).data;
    const seen = new Map();
    for (let i = 0; i < px.length; i += 4) {
      const k = (px[i] << 16) | (px[i + 1] << 8) | px[i + 2];
      seen.set(k, (seen.get(k) || 0) + 1);
    }
    const top = Math.max(...seen.values());
    return { distinct: seen.size, notBackground: 1 - top / (px.length / 4) };
  }, [shot.toString('base64'), box]);
  await probe.close();
  check(colours.distinct > 50 && colours.notBackground > 0.05,
    `the 3D view is drawn (${colours.distinct} colours, ${(100 * colours.notBackground).toFixed(0)} % not background)`);
  check(errors.length === 0, `no console or page errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);
} catch (e) {
  failures.push(`exception: ${e.message}`);
  console.log(`  FAIL ${e.stack}`);
  if (errors.length) console.log(`  errors seen: ${errors.join(' | ')}`);
} finally {
  await context.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
console.log(`viewer_e2e: ${passed} passed, ${failures.length} failed`);
process.exit(failures.length ? 1 : 0);
