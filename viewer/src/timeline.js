// Time helpers: the run's time span and the sample shown at a time t (the last
// sample at or before t), found by binary search in a sorted time array.

/** Index of the last entry of sorted `times` that is <= t (0 when t precedes all). */
export function sampleAt(times, t) {
  let lo = 0;
  let hi = times.length - 1;
  if (hi < 0 || t <= times[0]) return 0;
  if (t >= times[hi]) return hi;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (times[mid] <= t) lo = mid; else hi = mid - 1;
  }
  return lo;
}

/** Number of entries of sorted `times` that are <= t (ties at the first time
 *  included: several cells or points often share one sample's time). */
export function countUpTo(times, t) {
  let lo = 0;
  let hi = times.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= t) lo = mid + 1; else hi = mid;
  }
  return lo;
}

/** [start, end] of the run in seconds, over the sensors' and the poses' samples. */
export function timeSpan(data) {
  let start = Infinity;
  let end = -Infinity;
  const all = data.sensors.map((s) => s.t);
  if (data.poses) all.push(data.poses.t);
  for (const t of all) {
    if (!t.length) continue;
    start = Math.min(start, t[0]);
    end = Math.max(end, t[t.length - 1]);
  }
  if (!Number.isFinite(start)) return [0, data.scene.duration_s || 1];
  return [start, end];
}

/** The sampling step (s): the scene's rate, else the first sensor's spacing. */
export function timeStep(data) {
  if (data.scene.rate_hz) return 1 / data.scene.rate_hz;
  const t = data.sensors.length ? data.sensors[0].t : [];
  return t.length > 1 ? t[1] - t[0] : 0.02;
}
