// The profile growing with time: one point cloud per sensor (its detections in
// the world frame, sorted by time, coloured by the object hit), of which the
// points up to the time shown are drawn (a draw range, no rebuild).
import * as THREE from 'three';
import { countUpTo } from './timeline.js';

export class ProfileView {
  constructor(scene, profile, sensors, objectColors) {
    this.clouds = sensors.map((sensor) => {
      const idx = [];
      for (let k = 0; k < profile.sensor.length; k++) if (profile.sensor[k] === sensor.index) idx.push(k);
      const pos = new Float32Array(3 * idx.length);
      const col = new Float32Array(3 * idx.length);
      const times = new Float64Array(idx.length);
      const c = new THREE.Color();
      idx.forEach((k, m) => {
        pos[3 * m] = profile.x[k]; pos[3 * m + 1] = profile.y[k]; pos[3 * m + 2] = profile.z[k];
        c.set(objectColors[String(profile.object[k])] || '#222222');
        col[3 * m] = c.r; col[3 * m + 1] = c.g; col[3 * m + 2] = c.b;
        times[m] = profile.t_s[k];
      });
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      geometry.setAttribute('color', new THREE.BufferAttribute(col, 3));
      geometry.setDrawRange(0, 0);
      const points = new THREE.Points(geometry, new THREE.PointsMaterial({
        size: 5, sizeAttenuation: false, vertexColors: true,
      }));
      points.frustumCulled = false;
      scene.add(points);
      return { points, times };
    });
  }

  /** Shows each visible sensor's points detected up to time t. */
  update(t, visible) {
    this.clouds.forEach(({ points, times }, j) => {
      points.visible = visible[j];
      points.geometry.setDrawRange(0, countUpTo(times, t));
    });
  }

  /** Number of points drawn (for tests). */
  shownCount() {
    return this.clouds.reduce((n, { points }) => n + (points.visible ? points.geometry.drawRange.count : 0), 0);
  }
}
