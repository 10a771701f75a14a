// The Foxglove messages of a run (docs/foxglove.md): each topic as a name,
// its schema and a generator of {t_s, message} in time order. The messages
// are plain objects in the JSON encoding of Foxglove's schemas
// (@foxglove/schemas/jsonschema): times as {sec, nsec}, bytes as base64,
// every required field present. Frames: `world`, each robot link by its
// name (the link frames of poses.csv), each sensor as `sensor/NAME` (its
// mounting pose in its link, from summary.json's inputs; +x its axis).
// Nothing here writes: foxglove_export.mjs hands the topics to @mcap/core.
import schemas from '@foxglove/schemas/jsonschema.js';

/** The one schema that is not Foxglove's: a reading, one row of readings.csv (Foxglove publishes no range reading). */
export const READING_SCHEMA_NAME = 'proxsim.SensorReading';
/** The terrain map is published as it grew, every this much of simulated time, and at the last sample. */
export const MAP_PERIOD_S = 0.5;
/** An infinite plane is drawn as a square this wide. */
const PLANE_SIZE_M = 40;
/** A box at least this tall and this long is a wall: drawn see-through, as in the viewer. */
const WALL_HEIGHT_M = 1.0;
const WALL_LENGTH_M = 1.5;

// status colours as the viewer's: green detected, grey no echo, orange too close, red grazing, purple self
const STATUS_RGB = {
  ok: [0.17, 0.63, 0.17], no_echo: [0.5, 0.5, 0.5], too_close: [1.0, 0.5, 0.05], grazing: [0.84, 0.15, 0.16],
  self: [0.58, 0.4, 0.74], dropout: [0.35, 0.45, 0.55],
};
const HAZARD_RGB = {
  obstacle: [0.9, 0.49, 0.13], step_up: [0.16, 0.5, 0.73], step_down: [0.56, 0.27, 0.68], hole: [0.75, 0.22, 0.17],
};
// Foxglove's enumerations (foxglove.NumericType, foxglove.LineType, foxglove.LogLevel)
const NUMERIC = { UINT32: 6, INT32: 5, FLOAT32: 7 };
const LINE_STRIP = 0;
const LOG = { INFO: 2, WARNING: 3, ERROR: 4 };

/** A time in seconds as MCAP's nanoseconds (bigint), rounded to the nanosecond. */
export function toNanoseconds(t_s) {
  return BigInt(Math.round(t_s * 1e9));
}

/** A time in seconds as Foxglove's {sec, nsec}. */
function stamp(t_s) {
  const ns = toNanoseconds(t_s);
  return { sec: Number(ns / 1000000000n), nsec: Number(ns % 1000000000n) };
}

const vec = ([x, y, z]) => ({ x, y, z });
const quat = ([w, x, y, z]) => ({ x, y, z, w });
const pose = (xyz, wxyz = [1, 0, 0, 0]) => ({ position: vec(xyz), orientation: quat(wxyz) });
const rgba = ([r, g, b], a = 1) => ({ r, g, b, a });
// JSON has no NaN: a "none" is null
const orNull = (v) => (typeof v === 'number' && Number.isNaN(v) ? null : v);

/** R = Rz(yaw)·Ry(pitch)·Rx(roll), as URDF and the scenario, as a quaternion (w, x, y, z). */
export function quaternionFromRpy([roll, pitch, yaw]) {
  const [cr, sr] = [Math.cos(roll / 2), Math.sin(roll / 2)];
  const [cp, sp] = [Math.cos(pitch / 2), Math.sin(pitch / 2)];
  const [cy, sy] = [Math.cos(yaw / 2), Math.sin(yaw / 2)];
  return [cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr, sy * cp * sr + cy * sp * cr,
    sy * cp * cr - cy * sp * sr];
}

/** A scene entity with every field Foxglove's schema requires; `parts` fills the primitives. */
function entity(t_s, frame_id, id, parts, { frame_locked = false, metadata = [] } = {}) {
  return {
    timestamp: stamp(t_s), frame_id, id, lifetime: { sec: 0, nsec: 0 }, frame_locked, metadata,
    arrows: [], cubes: [], spheres: [], cylinders: [], lines: [], triangles: [], texts: [], models: [], ...parts,
  };
}

/** One shape of scene.json (an object's, or a link's in its link frame) as Foxglove primitives. */
function shapePrimitives(shape, color) {
  const at = pose(shape.xyz_m, shape.quat_wxyz);
  switch (shape.shape) {
    case 'box':
      return { cubes: [{ pose: at, size: vec(shape.size_m), color }] };
    case 'sphere': {
      const d = 2 * shape.radius_m;
      return { spheres: [{ pose: at, size: vec([d, d, d]), color }] };
    }
    case 'cylinder': {
      const d = 2 * shape.radius_m;
      return { cylinders: [{ pose: at, size: vec([d, d, shape.length_m]), bottom_scale: 1, top_scale: 1, color }] };
    }
    case 'plane': {
      const h = PLANE_SIZE_M / 2;
      const corners = [[-h, -h, 0], [h, -h, 0], [h, h, 0], [-h, h, 0]].map(vec);
      return { triangles: [{ pose: at, points: corners, color, colors: [], indices: [0, 1, 2, 0, 2, 3] }] };
    }
    case 'mesh':
      return {
        triangles: [{ pose: at, points: shape.vertices_m.map(vec), color, colors: [], indices: shape.triangles.flat() }],
      };
    default:
      throw new Error(`scene.json: unknown shape '${shape.shape}'`);
  }
}

// merges the primitives of several shapes into one entity's lists
function mergeParts(list) {
  const parts = {};
  for (const p of list) for (const [key, values] of Object.entries(p)) parts[key] = [...(parts[key] ?? []), ...values];
  return parts;
}

function isWall(object) {
  return object.shape === 'box' && object.size_m[2] >= WALL_HEIGHT_M && Math.max(object.size_m[0], object.size_m[1]) >= WALL_LENGTH_M;
}

function objectColor(object) {
  const a = Math.min(Math.max(object.albedo ?? 0.6, 0.05), 1);
  return rgba([0.55 + 0.35 * a, 0.52 + 0.33 * a, 0.47 + 0.3 * a], isWall(object) ? 0.2 : 1);
}

/** The sample times of the run: every time a reading or a pose was taken, sorted. */
export function sampleTimes(run) {
  const times = new Set(run.readings.columns.t_s);
  for (const sample of run.poses) times.add(sample.t_s);
  return [...times].filter((t) => !Number.isNaN(t)).sort((a, b) => a - b);
}

// /scene: the scene's objects, once, in the world frame
function* sceneMessages(run, t0) {
  const entities = run.scene.objects.map((object) => entity(t0, 'world', `object/${object.name}`,
    shapePrimitives(object, objectColor(object)), { metadata: [{ key: 'object', value: object.name }] }));
  yield { t_s: t0, message: { deletions: [], entities } };
}

// /robot: each link's shapes, once, in its own frame (locked to it: the transforms move them)
function* robotMessages(run, t0) {
  const color = rgba([0.31, 0.43, 0.56]);
  const entities = run.scene.robot.links.map((link) => entity(t0, link.name, `link/${link.name}`,
    mergeParts(link.shapes.map((shape) => shapePrimitives(shape, color))), { frame_locked: true }));
  yield { t_s: t0, message: { deletions: [], entities } };
}

/** Each sensor's mounting: its frame's parent (a link, or world) and pose there, from summary.json's inputs. */
function sensorMounts(run) {
  const inputs = run.summary.inputs?.sensors ?? [];
  return run.scene.sensors.map((sensor, i) => {
    const mount = inputs[i]?.pose ?? { xyz_m: [0, 0, 0], rpy_deg: [0, 0, 0] };
    return {
      parent_frame_id: sensor.link,
      child_frame_id: `sensor/${sensor.name}`,
      translation: vec(mount.xyz_m),
      rotation: quat(quaternionFromRpy(mount.rpy_deg.map((deg) => (deg * Math.PI) / 180))),
    };
  });
}

// /tf: the links' poses in the world at every sample of poses.csv, with the sensors' mountings
// (without a robot: the world-mounted sensors' frames, once)
function* transformMessages(run, t0) {
  const mounts = sensorMounts(run);
  const withStamp = (t_s, list) => list.map((tf) => ({ timestamp: stamp(t_s), ...tf }));
  if (run.poses.length === 0) {
    yield { t_s: t0, message: { transforms: withStamp(t0, mounts) } };
    return;
  }
  for (const sample of run.poses) {
    const links = sample.links.map((l) => ({
      parent_frame_id: 'world', child_frame_id: l.link, translation: vec(l.xyz), rotation: quat(l.wxyz),
    }));
    yield { t_s: sample.t_s, message: { transforms: withStamp(sample.t_s, [...links, ...mounts]) } };
  }
}

/** The rows of readings.csv for one sensor, in order. */
function rowsOf(run, name) {
  const rows = [];
  run.readings.columns.sensor.forEach((sensor, k) => { if (sensor === name) rows.push(k); });
  return rows;
}

/** The JSON schema of proxsim.SensorReading: one property per column of columns.json, with its unit and meaning. */
export function readingSchema(columnsMeta) {
  const properties = { timestamp: schemas.Time };
  for (const column of columnsMeta.columns) {
    const type = column.codes ? ['string', 'null'] : column.dtype === '|b1' ? 'boolean'
      : column.dtype.includes('f') ? ['number', 'null'] : 'integer';
    const unit = column.unit ? ` [${column.unit}]` : '';
    properties[column.name] = { type, description: `${column.meaning}${unit}` };
  }
  return {
    title: READING_SCHEMA_NAME,
    description: "One reading of a proxsim sensor: a row of the run's readings (docs/outputs.md); codes as their names, none as null",
    type: 'object',
    properties,
    required: Object.keys(properties),
  };
}

// /sensors/NAME/reading: the sensor's readings, one row each
function* readingMessages(run, rows) {
  const { columns, meta } = run.readings;
  for (const k of rows) {
    const message = { timestamp: stamp(columns.t_s[k]) };
    for (const column of meta.columns) message[column.name] = orNull(columns[column.name][k]);
    yield { t_s: columns.t_s[k], message };
  }
}

// /sensors/NAME/ray: the reading as a line from the sensor's origin along its axis to the distance it
// reports (d_max when it detects nothing), coloured by status, in the world frame
function* rayMessages(run, name, rows) {
  const c = run.readings.columns;
  for (const k of rows) {
    const origin = [c.origin_x_m[k], c.origin_y_m[k], c.origin_z_m[k]];
    const dir = [c.dir_x[k], c.dir_y[k], c.dir_z[k]];
    const end = origin.map((o, i) => o + c.d_m[k] * dir[i]);
    const color = rgba(STATUS_RGB[c.status[k]] ?? [0, 0, 0]);
    const line = {
      type: LINE_STRIP, pose: pose([0, 0, 0]), thickness: 3, scale_invariant: true,
      points: [vec(origin), vec(end)], color, colors: [], indices: [],
    };
    const metadata = [{ key: 'status', value: String(c.status[k]) }, { key: 'd_m', value: String(c.d_m[k]) }];
    yield {
      t_s: c.t_s[k],
      message: { deletions: [], entities: [entity(c.t_s[k], 'world', `ray/${name}`, { lines: [line] }, { metadata })] },
    };
  }
}

// /profile: the points detected at each sample (x, y, z, sensor index, object id), as a point cloud
// of that sample's new points; Foxglove's decay time accumulates them
function* profileMessages(run) {
  const p = run.profile;
  const fields = [
    { name: 'x', offset: 0, type: NUMERIC.FLOAT32 }, { name: 'y', offset: 4, type: NUMERIC.FLOAT32 },
    { name: 'z', offset: 8, type: NUMERIC.FLOAT32 }, { name: 'sensor', offset: 12, type: NUMERIC.UINT32 },
    { name: 'object', offset: 16, type: NUMERIC.INT32 },
  ];
  const stride = 20;
  for (let start = 0; start < p.count;) {
    let end = start;
    while (end < p.count && p.t_s[end] === p.t_s[start]) end += 1;
    const data = Buffer.alloc((end - start) * stride);
    for (let k = start; k < end; k += 1) {
      const at = (k - start) * stride;
      data.writeFloatLE(p.x[k], at);
      data.writeFloatLE(p.y[k], at + 4);
      data.writeFloatLE(p.z[k], at + 8);
      data.writeUInt32LE(p.sensor[k], at + 12);
      data.writeInt32LE(p.object[k], at + 16);
    }
    yield {
      t_s: p.t_s[start],
      message: {
        timestamp: stamp(p.t_s[start]), frame_id: 'world', pose: pose([0, 0, 0]), point_stride: stride, fields,
        data: data.toString('base64'),
      },
    };
    start = end;
  }
}

/** A terrain grid message: the named float32 arrays of terrain/ as fields, NaN where `known(i)` is false. */
function gridMessage(terrain, t_s, names, known) {
  const [ny, nx] = terrain.meta.shape;
  const r = terrain.meta.resolution_m;
  const [x0, y0] = terrain.meta.origin_xy_m;
  const stride = 4 * names.length;
  const data = Buffer.alloc(nx * ny * stride);
  for (let i = 0; i < nx * ny; i += 1) {
    names.forEach((name, f) => data.writeFloatLE(known(i) ? terrain.arrays[name][i] : NaN, i * stride + 4 * f));
  }
  return {
    timestamp: stamp(t_s), frame_id: 'world', pose: pose([x0, y0, 0]), column_count: nx, cell_size: { x: r, y: r },
    row_stride: nx * stride, cell_stride: stride,
    fields: names.map((name, f) => ({ name, offset: 4 * f, type: NUMERIC.FLOAT32 })),
    data: data.toString('base64'),
  };
}

/** When /terrain/map is published: the first sample of each MAP_PERIOD_S, and the last sample. */
export function mapTimes(times) {
  const chosen = [];
  let period = -1;
  for (const t of times) {
    const p = Math.floor(t / MAP_PERIOD_S + 1e-9);
    if (p !== period) { chosen.push(t); period = p; }
  }
  if (times.length > 0 && chosen[chosen.length - 1] !== times[times.length - 1]) chosen.push(times[times.length - 1]);
  return chosen;
}

// /terrain/map: the map as it grew: each cell from the time it first held a height, with its final
// height and variance (the run keeps no history of a cell's values)
function* mapMessages(terrain, times) {
  const first = terrain.arrays.first_update_t_s;
  for (const t of mapTimes(times)) {
    yield { t_s: t, message: gridMessage(terrain, t, ['elevation', 'variance'], (i) => first[i] <= t + 1e-9) };
  }
}

// /terrain/truth: the scene's true height field, once
function* truthMessages(terrain, t0) {
  yield { t_s: t0, message: gridMessage(terrain, t0, ['truth'], () => true) };
}

/** The height of the map (else the truth, else 0) at the cell holding (x, y). */
function heightAt(terrain, x, y) {
  const [ny, nx] = terrain.meta.shape;
  const r = terrain.meta.resolution_m;
  const [x0, y0] = terrain.meta.origin_xy_m;
  const i = Math.floor((y - y0) / r);
  const j = Math.floor((x - x0) / r);
  if (i < 0 || j < 0 || i >= ny || j >= nx) return 0;
  for (const name of ['elevation', 'truth']) if (!Number.isNaN(terrain.arrays[name][i * nx + j])) return terrain.arrays[name][i * nx + j];
  return 0;
}

// /terrain/hazards: each hazard when the map found it, a box over its extent and height, labelled
function* hazardMessages(terrain) {
  const hazards = [...terrain.hazards].sort((a, b) => a.first_detection_t_s - b.first_detection_t_s);
  for (const [k, h] of hazards.entries()) {
    // an obstacle stands on the ground below the map's height there; a drop goes down from it
    const z = heightAt(terrain, h.x_m, h.y_m);
    const bottom = z - Math.max(h.height_m, 0);
    const top = z + Math.max(-h.height_m, 0);
    const size = [h.size_x_m, h.size_y_m, Math.max(top - bottom, 0.01)];
    const color = rgba(HAZARD_RGB[h.class] ?? [0.8, 0.2, 0.2], 0.5);
    const parts = {
      cubes: [{ pose: pose([h.x_m, h.y_m, (bottom + top) / 2]), size: vec(size), color }],
      texts: [{ pose: pose([h.x_m, h.y_m, top + 0.1]), billboard: true, font_size: 14, scale_invariant: true, color: rgba([0, 0, 0]), text: h.class }],
    };
    const metadata = [{ key: 'class', value: h.class }, { key: 'height_m', value: String(h.height_m) }];
    yield {
      t_s: h.first_detection_t_s,
      message: { deletions: [], entities: [entity(h.first_detection_t_s, 'world', `hazard/${k}`, parts, { metadata })] },
    };
  }
}

// /events: the summary's warnings (at the start), the robot's events and its outcome, as log lines
function* eventMessages(run, t0, tEnd) {
  const logs = (run.summary.warnings ?? []).map((w) => ({ t_s: t0, level: LOG.WARNING, name: 'proxsim', message: w }));
  const robot = run.summary.robot;
  if (robot) {
    const serious = new Set(['collision', 'fall', 'cannot_step']);
    for (const e of robot.events ?? []) {
      logs.push({ t_s: e.t_s, level: serious.has(e.event) ? LOG.WARNING : LOG.INFO, name: 'robot', message: `${e.event}: ${e.detail}` });
    }
    if (robot.outcome) {
      logs.push({
        t_s: robot.outcome_t_s ?? tEnd, level: ['collided', 'fell'].includes(robot.outcome) ? LOG.ERROR : LOG.INFO,
        name: 'outcome', message: `${robot.outcome}: ${robot.outcome_detail}`,
      });
    }
  }
  logs.sort((a, b) => a.t_s - b.t_s);  // stable: warnings, then events in order, the outcome last
  for (const { t_s, level, name, message } of logs) {
    yield { t_s, message: { timestamp: stamp(t_s), level, message, name, file: '', line: 0 } };
  }
}

/**
 * The run's topics in publishing order: {topic, schema (a JSON schema, its title the schema's
 * name), messages: a generator of {t_s, message} in time order}. A topic with nothing to say (no
 * robot, no map, no events) is left out.
 */
export function runTopics(run) {
  const times = sampleTimes(run);
  const t0 = times[0] ?? 0;
  const tEnd = times[times.length - 1] ?? 0;
  const topics = [{ topic: '/scene', schema: schemas.SceneUpdate, messages: sceneMessages(run, t0) }];
  if (run.scene.robot) topics.push({ topic: '/robot', schema: schemas.SceneUpdate, messages: robotMessages(run, t0) });
  topics.push({ topic: '/tf', schema: schemas.FrameTransforms, messages: transformMessages(run, t0) });
  const reading = readingSchema(run.readings.meta);
  for (const sensor of run.scene.sensors) {
    const rows = rowsOf(run, sensor.name);
    if (rows.length === 0) continue;
    topics.push({ topic: `/sensors/${sensor.name}/reading`, schema: reading, messages: readingMessages(run, rows) });
    topics.push({ topic: `/sensors/${sensor.name}/ray`, schema: schemas.SceneUpdate, messages: rayMessages(run, sensor.name, rows) });
  }
  if (run.profile.count > 0) topics.push({ topic: '/profile', schema: schemas.PointCloud, messages: profileMessages(run) });
  if (run.terrain) {
    topics.push({ topic: '/terrain/map', schema: schemas.Grid, messages: mapMessages(run.terrain, times) });
    topics.push({ topic: '/terrain/truth', schema: schemas.Grid, messages: truthMessages(run.terrain, t0) });
    if (run.terrain.hazards.length > 0) {
      topics.push({ topic: '/terrain/hazards', schema: schemas.SceneUpdate, messages: hazardMessages(run.terrain) });
    }
  }
  const hasEvents = (run.summary.warnings ?? []).length > 0 || run.summary.robot;
  if (hasEvents) topics.push({ topic: '/events', schema: schemas.Log, messages: eventMessages(run, t0, tEnd) });
  return topics;
}
