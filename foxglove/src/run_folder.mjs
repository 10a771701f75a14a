// Reads a finished run's folder (docs/outputs.md) into plain arrays: the
// scene (scene.json), the summary, the readings (readings.csv, or readings/
// with --format npy; their columns as columns.json declares them), the link
// poses (poses.csv), the profile (profile.ply) and the terrain map
// (terrain/). Only the files' documented formats are read; a file that does
// not parse is a RunFolderError naming it (the exporter's exit 2).
import fs from 'node:fs';
import path from 'node:path';

/** Bad input: a missing or malformed run file; the message names it. */
export class RunFolderError extends Error {}

function readText(file) {
  try {
    return fs.readFileSync(file, 'utf8');
  } catch (error) {
    throw new RunFolderError(`${file}: cannot read it (${error.code ?? error.message})`);
  }
}

function readJson(file) {
  const text = readText(file);
  try {
    return JSON.parse(text);
  } catch (error) {
    throw new RunFolderError(`${file}: not JSON (${error.message})`);
  }
}

/** The records of a CSV text (RFC 4180: a quoted field may hold commas, doubled quotes, line breaks). */
export function parseCsv(text) {
  const records = [];
  let fields = [''];
  let quoted = false;
  for (let i = 0; i < text.length; i += 1) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { fields[fields.length - 1] += '"'; i += 1; }
      else if (c === '"') quoted = false;
      else fields[fields.length - 1] += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') fields.push('');
    else if (c === '\n') { records.push(fields); fields = ['']; }
    else if (c !== '\r') fields[fields.length - 1] += c;
  }
  if (fields.length > 1 || fields[0] !== '') records.push(fields);
  return records;
}

/** A CSV file as {header, rows}; `expected` columns must all be in its header. */
function readCsv(file, expected) {
  const [header, ...rows] = parseCsv(readText(file));
  const missing = expected.filter((name) => !(header ?? []).includes(name));
  if (!header || missing.length > 0) {
    throw new RunFolderError(`${file}: expected the columns ${expected.join(',')}; missing ${missing.join(',')}`);
  }
  rows.forEach((row, k) => {
    if (row.length !== header.length) {
      throw new RunFolderError(`${file}:${k + 2}: ${row.length} fields where the header has ${header.length}`);
    }
  });
  return { header, rows };
}

// an empty CSV field is "none": NaN for a float
const number = (text) => (text === '' ? NaN : Number(text));

// the dtypes proxsim writes in .npy files, as typed-array constructors
const NPY_TYPES = {
  '<f8': Float64Array, '<f4': Float32Array, '<i4': Int32Array, '<u4': Uint32Array, '|u1': Uint8Array, '|b1': Uint8Array,
};

/** A 1- or 2-dimensional little-endian .npy file (format 1.0 or 2.0) as {shape, data}. */
export function readNpy(file) {
  let bytes;
  try {
    bytes = fs.readFileSync(file);
  } catch (error) {
    throw new RunFolderError(`${file}: cannot read it (${error.code ?? error.message})`);
  }
  if (bytes.length < 10 || bytes.toString('latin1', 0, 6) !== '\x93NUMPY') {
    throw new RunFolderError(`${file}: not a NumPy .npy file`);
  }
  const major = bytes[6];
  const headerLength = major === 1 ? bytes.readUInt16LE(8) : bytes.readUInt32LE(8);
  const headerStart = major === 1 ? 10 : 12;
  const header = bytes.toString('latin1', headerStart, headerStart + headerLength);
  const descr = /'descr':\s*'([^']+)'/.exec(header)?.[1];
  const fortran = /'fortran_order':\s*True/.test(header);
  const shapeText = /'shape':\s*\(([^)]*)\)/.exec(header)?.[1];
  const Type = NPY_TYPES[descr];
  if (!Type || fortran || shapeText === undefined) {
    throw new RunFolderError(`${file}: unsupported .npy header ${header.trim()}`);
  }
  const shape = shapeText.split(',').map((s) => s.trim()).filter((s) => s !== '').map(Number);
  const count = shape.reduce((a, b) => a * b, 1);
  const start = headerStart + headerLength;
  if (bytes.length - start !== count * Type.BYTES_PER_ELEMENT) {
    throw new RunFolderError(`${file}: ${bytes.length - start} data bytes where shape (${shape}) needs ${count * Type.BYTES_PER_ELEMENT}`);
  }
  // copied out: the file's buffer need not be aligned for the type
  const data = new Type(bytes.buffer.slice(bytes.byteOffset + start, bytes.byteOffset + bytes.length));
  return { shape, data };
}

/**
 * The readings as columns, in the file's row order: `columns` (name → array:
 * numbers with NaN for none; a coded column as its names, null for none;
 * `detected` as booleans) and `meta`, columns.json (each column's dtype,
 * unit and meaning).
 */
function readReadings(dir, summary) {
  const npy = (summary.outputs ?? []).includes('readings/') || !fs.existsSync(path.join(dir, 'readings.csv'));
  const meta = readJson(path.join(dir, npy ? 'readings' : '', 'columns.json'));
  const columns = {};
  if (npy) {
    for (const column of meta.columns) {
      const { data } = readNpy(path.join(dir, 'readings', `${column.name}.npy`));
      if (column.codes) {
        const names = meta[column.codes];
        columns[column.name] = Array.from(data, (code) => names[code] ?? null);
      } else if (column.dtype === '|b1') {
        columns[column.name] = Array.from(data, (v) => v !== 0);
      } else {
        columns[column.name] = Array.from(data);
      }
    }
  } else {
    const file = path.join(dir, 'readings.csv');
    const names = meta.columns.map((c) => c.name);
    const { header, rows } = readCsv(file, names);
    for (const column of meta.columns) {
      const at = header.indexOf(column.name);
      columns[column.name] = rows.map((row) => {
        const text = row[at];
        if (column.codes) return text === '' ? null : text;
        if (column.dtype === '|b1') return text === '1';
        return number(text);
      });
    }
  }
  return { columns, meta, rows: columns.t_s.length };
}

/** poses.csv: per sample time, each link's position and orientation (w, x, y, z). */
function readPoses(dir) {
  const file = path.join(dir, 'poses.csv');
  if (!fs.existsSync(file)) return [];
  const { rows } = readCsv(file, ['t_s', 'link', 'x', 'y', 'z', 'qw', 'qx', 'qy', 'qz']);
  const samples = [];
  for (const [t, link, x, y, z, qw, qx, qy, qz] of rows) {
    const t_s = Number(t);
    if (samples.length === 0 || samples[samples.length - 1].t_s !== t_s) samples.push({ t_s, links: [] });
    samples[samples.length - 1].links.push({ link, xyz: [x, y, z].map(Number), wxyz: [qw, qx, qy, qz].map(Number) });
  }
  return samples;
}

/** profile.ply (ASCII): its vertices as columns of its declared properties. */
function readProfile(dir) {
  const file = path.join(dir, 'profile.ply');
  const lines = readText(file).split('\n');
  const end = lines.indexOf('end_header');
  if (lines[0] !== 'ply' || end < 0) throw new RunFolderError(`${file}: not an ASCII PLY file`);
  let count = 0;
  const properties = [];
  for (const line of lines.slice(1, end)) {
    const words = line.trim().split(/\s+/);
    if (words[0] === 'element' && words[1] === 'vertex') count = Number(words[2]);
    if (words[0] === 'property') properties.push(words[2]);
  }
  const profile = Object.fromEntries(properties.map((name) => [name, new Float64Array(count)]));
  for (let k = 0; k < count; k += 1) {
    const values = (lines[end + 1 + k] ?? '').trim().split(/\s+/);
    if (values.length !== properties.length) throw new RunFolderError(`${file}: vertex ${k} has ${values.length} values, not ${properties.length}`);
    properties.forEach((name, p) => { profile[name][k] = Number(values[p]); });
  }
  return { count, ...profile };
}

/** terrain/: meta.json, its arrays by name (without .npy) and hazards.csv; null when the run has no map. */
function readTerrain(dir) {
  const folder = path.join(dir, 'terrain');
  if (!fs.existsSync(path.join(folder, 'meta.json'))) return null;
  const meta = readJson(path.join(folder, 'meta.json'));
  const arrays = {};
  for (const name of meta.arrays) arrays[name.replace(/\.npy$/, '')] = readNpy(path.join(folder, name)).data;
  const hazardColumns = ['class', 'x_m', 'y_m', 'size_x_m', 'size_y_m', 'height_m', 'first_detection_t_s'];
  const { header, rows } = readCsv(path.join(folder, 'hazards.csv'), hazardColumns);
  const hazards = rows.map((row) => Object.fromEntries(header.map((name, i) => [name, name === 'class' ? row[i] : number(row[i])])));
  return { meta, arrays, hazards };
}

/** The whole run in `dir`: {scene, summary, readings, poses, profile, terrain}. */
export function readRunFolder(dir) {
  if (!fs.existsSync(path.join(dir, 'summary.json'))) {
    throw new RunFolderError(`${dir}: not a run's output folder (no summary.json)`);
  }
  const summary = readJson(path.join(dir, 'summary.json'));
  const scene = readJson(path.join(dir, 'scene.json'));
  return {
    dir,
    scene,
    summary,
    readings: readReadings(dir, summary),
    poses: readPoses(dir),
    profile: readProfile(dir),
    terrain: readTerrain(dir),
  };
}
