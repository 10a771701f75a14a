// Reads an MCAP file written by `proxsim export` / `proxsim run --mcap` back
// with @mcap/core's indexed reader (CRCs validated) and checks it against the
// run it came from (docs/foxglove.md):
//  - every topic the run calls for, and no other; each message count and each
//    topic's time range, against summary.json and the run's own files;
//  - every schema is Foxglove's as @foxglove/schemas publishes it (JSON schema,
//    JSON messages), but the readings' own proxsim.SensorReading;
//  - every message holds every field its schema requires, of the right type;
//  - the contents: each reading's values, the links' and sensors' transforms,
//    the profile's points, the final terrain map, the scene's entities.
//
//   node tests/foxglove/mcap_readback.mjs RUN_DIR FILE.mcap [--foxglove-dir foxglove]
//
// Exit 0 pass, 1 fail, 2 usage.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const option = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const [runDir, mcapPath] = process.argv.slice(2);
if (!runDir || !mcapPath || runDir.startsWith('--')) {
  console.error('usage: node mcap_readback.mjs RUN_DIR FILE.mcap [--foxglove-dir DIR]');
  process.exit(2);
}
// the libraries live in the exporter's node_modules
const foxgloveDir = path.resolve(option('--foxglove-dir', path.join(here, '..', '..', 'foxglove')));
const requireThere = createRequire(path.join(foxgloveDir, 'package.json'));
const { McapIndexedReader } = requireThere('@mcap/core');
const { FileHandleReadable } = requireThere('@mcap/nodejs');
const foxgloveSchemas = requireThere('@foxglove/schemas/jsonschema.js');
// the run's files, read by the exporter's reader of the documented formats (its counts are
// checked against summary.json's below, so a misread shows)
const { readRunFolder } = await import(pathToFileURL(path.join(foxgloveDir, 'src', 'run_folder.mjs')).href);

let passed = 0;
const failures = [];
function check(ok, what) {
  if (ok) passed += 1;
  else { failures.push(what); console.log(`  FAIL ${what}`); }
}
const near = (a, b, tol) => Math.abs(a - b) <= tol;
const ns = (t_s) => BigInt(Math.round(t_s * 1e9));

// a JSON-schema check of the parts Foxglove's schemas use: type, properties, required, items, oneOf of consts
function schemaProblems(value, schema, where) {
  const problems = [];
  const types = [].concat(schema.type ?? []);
  if (schema.oneOf) {
    if (!schema.oneOf.some((s) => s.const === value)) problems.push(`${where}: ${JSON.stringify(value)} is none of the enumeration`);
    return problems;
  }
  const typeOf = (v) => (v === null ? 'null' : Array.isArray(v) ? 'array' : Number.isInteger(v) ? 'integer' : typeof v);
  const t = typeOf(value);
  if (types.length > 0 && !types.includes(t) && !(t === 'integer' && types.includes('number'))) {
    problems.push(`${where}: ${t} where the schema says ${types.join('|')}`);
    return problems;
  }
  if (t === 'object') {
    for (const name of schema.required ?? []) if (!(name in value)) problems.push(`${where}.${name}: missing`);
    for (const [name, sub] of Object.entries(schema.properties ?? {})) {
      if (name in value) problems.push(...schemaProblems(value[name], sub, `${where}.${name}`));
    }
  }
  if (t === 'array' && schema.items) value.forEach((v, i) => problems.push(...schemaProblems(v, schema.items, `${where}[${i}]`)));
  return problems;
}

// the run and the file
const run = readRunFolder(runDir);
const summary = run.summary;
const handle = await fs.promises.open(mcapPath, 'r');
const reader = await McapIndexedReader.Initialize({ readable: new FileHandleReadable(handle) });
const channels = new Map([...reader.channelsById.values()].map((c) => [c.topic, c]));
const messages = new Map([...channels.keys()].map((topic) => [topic, []]));
const decoder = new TextDecoder();
for await (const record of reader.readMessages({ validateCrcs: true })) {
  const topic = reader.channelsById.get(record.channelId).topic;
  messages.get(topic).push({ t: record.logTime, publish: record.publishTime, message: JSON.parse(decoder.decode(record.data)) });
}
const metadata = [];
for await (const record of reader.readMetadata()) metadata.push(record);
await handle.close();

// what the run says: sample times, sensors, links
const rate = summary.inputs.rate_hz;
const sampleTimes = Array.from({ length: summary.samples }, (_, k) => run.readings.columns.t_s.find((t) => near(t, k / rate, 1e-9)) ?? k / rate);
const t0 = sampleTimes[0];
const tEnd = sampleTimes[sampleTimes.length - 1];
const sensors = run.scene.sensors.filter((s) => summary.sensors[s.name].samples > 0);
const robot = run.scene.robot;
const events = summary.robot ? summary.robot.events.length + (summary.robot.outcome ? 1 : 0) : 0;
const logs = summary.warnings.length + events;
const profileTimes = new Set(run.profile.t_s).size;
// the map: the first sample of each half second, and the last sample
const mapCount = (() => {
  const periods = new Set(sampleTimes.map((t) => Math.floor(t / 0.5 + 1e-9)));
  const lastIsFirstOfItsPeriod = sampleTimes.length < 2
    || Math.floor(sampleTimes[sampleTimes.length - 2] / 0.5 + 1e-9) !== Math.floor(tEnd / 0.5 + 1e-9);
  return periods.size + (lastIsFirstOfItsPeriod ? 0 : 1);
})();

// every topic, its count, its time range
const expected = new Map([['/scene', { count: 1, from: t0, to: t0 }]]);
if (robot) expected.set('/robot', { count: 1, from: t0, to: t0 });
expected.set('/tf', robot ? { count: summary.samples, from: t0, to: tEnd } : { count: 1, from: t0, to: t0 });
for (const s of sensors) {
  const times = run.readings.columns.t_s.filter((_, k) => run.readings.columns.sensor[k] === s.name);
  const range = { count: summary.sensors[s.name].samples, from: times[0], to: times[times.length - 1] };
  expected.set(`/sensors/${s.name}/reading`, range);
  expected.set(`/sensors/${s.name}/ray`, range);
}
if (summary.profile_points > 0) {
  expected.set('/profile', { count: profileTimes, from: run.profile.t_s[0], to: run.profile.t_s[run.profile.count - 1] });
}
if (run.terrain) {
  expected.set('/terrain/map', { count: mapCount, from: t0, to: tEnd });
  expected.set('/terrain/truth', { count: 1, from: t0, to: t0 });
  const found = run.terrain.hazards.map((h) => h.first_detection_t_s);
  if (found.length > 0) expected.set('/terrain/hazards', { count: found.length, from: Math.min(...found), to: Math.max(...found) });
}
if (logs > 0) expected.set('/events', { count: logs, from: null, to: null });

check(run.readings.rows === Object.values(summary.sensors).reduce((a, s) => a + s.samples, 0),
  `the run's readings: ${run.readings.rows} rows, as summary.json counts`);
check(run.profile.count === summary.profile_points, `the run's profile: ${run.profile.count} points, as summary.json counts`);
check(JSON.stringify([...channels.keys()].sort()) === JSON.stringify([...expected.keys()].sort()),
  `topics: ${[...channels.keys()].join(' ')} (expected ${[...expected.keys()].join(' ')})`);
for (const [topic, want] of expected) {
  const got = messages.get(topic) ?? [];
  check(got.length === want.count, `${topic}: ${got.length} messages, expected ${want.count}`);
  if (got.length === 0) continue;
  if (want.from !== null) {
    check(got[0].t === ns(want.from) && got[got.length - 1].t === ns(want.to),
      `${topic}: time range ${got[0].t}..${got[got.length - 1].t} ns, expected ${ns(want.from)}..${ns(want.to)}`);
  }
  check(got.every((m, k) => m.t === m.publish && (k === 0 || m.t >= got[k - 1].t)), `${topic}: times ordered, log = publish`);
  check(got.every((m) => m.t >= ns(t0) && m.t <= ns(tEnd)), `${topic}: every message within the run's ${t0}..${tEnd} s`);
}
const total = [...messages.values()].reduce((a, list) => a + list.length, 0);
check(reader.statistics && reader.statistics.messageCount === BigInt(total), `statistics: ${reader.statistics?.messageCount} messages`);
check(reader.statistics.messageStartTime === ns(t0) && reader.statistics.messageEndTime === ns(tEnd),
  `statistics: the file spans the run, ${reader.statistics.messageStartTime}..${reader.statistics.messageEndTime} ns`);
check(metadata.some((m) => m.name === 'proxsim' && m.metadata.get('seed') === String(summary.inputs.seed)),
  "metadata 'proxsim' holds the run's seed");

// schemas: Foxglove's as published, but the readings'
const published = new Map(Object.values(foxgloveSchemas).map((s) => [s.title, s]));
for (const [topic, channel] of channels) {
  const schema = reader.schemasById.get(channel.schemaId);
  const body = JSON.parse(decoder.decode(schema.data));
  check(schema.encoding === 'jsonschema' && channel.messageEncoding === 'json', `${topic}: jsonschema / json`);
  if (topic.endsWith('/reading')) {
    check(schema.name === 'proxsim.SensorReading', `${topic}: schema ${schema.name}`);
    const columns = run.readings.meta.columns.map((c) => c.name);
    check(columns.every((name) => name in body.properties), `${topic}: the schema has every column of columns.json`);
  } else {
    check(schema.name.startsWith('foxglove.') && published.has(schema.name)
      && JSON.stringify(body) === JSON.stringify(published.get(schema.name)),
      `${topic}: schema ${schema.name} is Foxglove's published one`);
  }
  // every message as its schema requires
  const problems = (messages.get(topic) ?? []).flatMap((m, k) => schemaProblems(m.message, body, `${topic}#${k}`));
  check(problems.length === 0, `${topic}: messages match the schema${problems.length ? `: ${problems.slice(0, 3).join('; ')}` : ''}`);
}

// contents: readings, value by value
const c = run.readings.columns;
for (const s of sensors) {
  const rows = c.t_s.map((_, k) => k).filter((k) => c.sensor[k] === s.name);
  const got = messages.get(`/sensors/${s.name}/reading`);
  const rays = messages.get(`/sensors/${s.name}/ray`);
  const same = (a, b) => (Number.isNaN(b) ? a === null : a === b);
  if (got.length !== rows.length || rays.length !== rows.length) continue;  // counted above
  let bad = 0;
  rows.forEach((k, i) => {
    const m = got[i].message;
    if (got[i].t !== ns(c.t_s[k]) || m.status !== c.status[k] || m.detected !== c.detected[k] || !same(m.d_m, c.d_m[k])
      || !same(m.d_true_m, c.d_true_m[k]) || m.object !== c.object[k]) bad += 1;
    // the ray: from the origin along the axis to d_m
    const [a, b] = rays[i].message.entities[0].lines[0].points;
    const end = [c.origin_x_m[k] + c.d_m[k] * c.dir_x[k], c.origin_y_m[k] + c.d_m[k] * c.dir_y[k], c.origin_z_m[k] + c.d_m[k] * c.dir_z[k]];
    if (!near(a.x, c.origin_x_m[k], 1e-12) || !near(b.x, end[0], 1e-12) || !near(b.y, end[1], 1e-12) || !near(b.z, end[2], 1e-12)) bad += 1;
  });
  check(bad === 0, `/sensors/${s.name}: every reading and ray equals its row of the run (${bad} differ)`);
}

// transforms: each link where poses.csv has it; each sensor on its link at its mounting
const tf = messages.get('/tf');
if (robot) {
  let bad = tf.length === run.poses.length ? 0 : 1;
  run.poses.slice(0, tf.length).forEach((sample, k) => {
    const byChild = new Map(tf[k].message.transforms.map((x) => [x.child_frame_id, x]));
    for (const l of sample.links) {
      const x = byChild.get(l.link);
      if (!x || x.parent_frame_id !== 'world' || x.translation.x !== l.xyz[0] || x.translation.z !== l.xyz[2] || x.rotation.w !== l.wxyz[0]) bad += 1;
    }
  });
  check(bad === 0, `/tf: every link's pose as poses.csv has it (${bad} differ)`);
  const entities = messages.get('/robot')[0].message.entities;
  check(entities.length === robot.links.length && entities.every((e, i) => e.frame_id === robot.links[i].name && e.frame_locked),
    '/robot: one entity per link, locked to its frame');
}
summary.inputs.sensors.forEach((input, i) => {
  const mount = tf[0].message.transforms.find((x) => x.child_frame_id === `sensor/${input.name}`);
  check(mount && mount.parent_frame_id === input.link && near(mount.translation.x, input.pose.xyz_m[0], 1e-12)
    && near(mount.translation.z, input.pose.xyz_m[2], 1e-12)
    // the pitch of a sensor mounted with roll = yaw = 0: q = (cos(p/2), 0, sin(p/2), 0)
    && (input.pose.rpy_deg[0] !== 0 || input.pose.rpy_deg[2] !== 0
      || near(mount.rotation.y, Math.sin((input.pose.rpy_deg[1] * Math.PI) / 360), 1e-12)),
  `/tf: sensor/${input.name} mounted on ${input.link} at its pose (#${i})`);
});
check(messages.get('/scene')[0].message.entities.length === run.scene.objects.length, '/scene: one entity per object');

// the profile's points, decoded
if (summary.profile_points > 0) {
  let k = 0;
  let bad = 0;
  for (const { message } of messages.get('/profile')) {
    const data = Buffer.from(message.data, 'base64');
    for (let at = 0; at < data.length; at += message.point_stride, k += 1) {
      if (data.readFloatLE(at) !== Math.fround(run.profile.x[k]) || data.readFloatLE(at + 8) !== Math.fround(run.profile.z[k])
        || data.readUInt32LE(at + 12) !== run.profile.sensor[k]) bad += 1;
    }
  }
  check(k === run.profile.count && bad === 0, `/profile: ${k} points, as profile.ply (${bad} differ)`);
}

// the final terrain map is terrain/elevation.npy, cell by cell
if (run.terrain) {
  const grids = messages.get('/terrain/map');
  const last = grids[grids.length - 1].message;
  const data = Buffer.from(last.data, 'base64');
  const elevation = run.terrain.arrays.elevation;
  const whole = data.length === elevation.length * last.cell_stride;
  let bad = whole ? 0 : elevation.length;
  for (let i = 0; whole && i < elevation.length; i += 1) {
    const v = data.readFloatLE(i * last.cell_stride);
    if (!(Number.isNaN(v) && Number.isNaN(elevation[i])) && v !== elevation[i]) bad += 1;
  }
  const [ny, nx] = run.terrain.meta.shape;
  check(last.column_count === nx && data.length === nx * ny * last.cell_stride && bad === 0,
    `/terrain/map: the last grid is the final map, ${nx} x ${ny} cells (${bad} differ)`);
}

console.log(`mcap_readback: ${mcapPath}: ${total} messages on ${channels.size} topics`);
console.log(`${passed} passed, ${failures.length} failed`);
process.exit(failures.length === 0 ? 0 : 1);
