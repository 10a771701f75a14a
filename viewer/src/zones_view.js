// A multi-zone sensor's zones at the sample shown: each zone's nearest target
// as a point, and the zone grid drawn through them (each zone joined to its
// right and lower neighbours when both have a target), in the sensor's
// colour. Buffers are allocated once per sensor and rewritten every frame.
import * as THREE from 'three';
import { sampleAt } from './timeline.js';

export class ZonesView {
  /** zones: data.zones ({sensor, nx, ny, t, p}); sensors: data.sensors (for colour and visibility). */
  constructor(scene, zones, sensors) {
    this.grids = (zones || []).map((z) => {
      const slot = sensors.findIndex((s) => s.index === z.sensor);
      const count = z.nx * z.ny;
      const color = new THREE.Color(slot >= 0 ? sensors[slot].color : '#222222');
      const points = new Float32Array(3 * count);
      const pointGeometry = new THREE.BufferGeometry();
      pointGeometry.setAttribute('position', new THREE.BufferAttribute(points, 3));
      const cloud = new THREE.Points(pointGeometry, new THREE.PointsMaterial({ size: 7, sizeAttenuation: false, color }));
      cloud.frustumCulled = false;
      // at most one segment to the right and one below per zone
      const lines = new Float32Array(2 * 2 * 3 * count);
      const lineGeometry = new THREE.BufferGeometry();
      lineGeometry.setAttribute('position', new THREE.BufferAttribute(lines, 3));
      const grid = new THREE.LineSegments(lineGeometry, new THREE.LineBasicMaterial({ color, transparent: true, opacity: 0.6 }));
      grid.frustumCulled = false;
      scene.add(cloud);
      scene.add(grid);
      return { z, slot, count, points, lines, cloud, grid, shown: 0 };
    });
  }

  /** Redraws every grid at time t; a sensor whose `visible[slot]` is false shows nothing. */
  update(t, visible) {
    for (const g of this.grids) {
      const { z } = g;
      const on = g.slot < 0 || visible[g.slot];
      const i = z.t.length > 0 && t >= z.t[0] ? sampleAt(z.t, t) : -1;
      const at = (zone) => {
        const k = 3 * (i * g.count + zone);
        const x = z.p[k];
        return on && i >= 0 && x !== null ? [x, z.p[k + 1], z.p[k + 2]] : null;
      };
      let points = 0;
      let segments = 0;
      for (let zone = 0; zone < g.count; zone++) {
        const p = at(zone);
        if (!p) continue;
        g.points.set(p, 3 * points++);
        const column = zone % z.nx;
        for (const next of [column + 1 < z.nx ? zone + 1 : -1, zone + z.nx < g.count ? zone + z.nx : -1]) {
          const q = next >= 0 ? at(next) : null;
          if (!q) continue;
          g.lines.set(p, 6 * segments);
          g.lines.set(q, 6 * segments + 3);
          segments += 1;
        }
      }
      g.shown = points;
      g.cloud.geometry.setDrawRange(0, points);
      g.grid.geometry.setDrawRange(0, 2 * segments);
      g.cloud.geometry.attributes.position.needsUpdate = true;
      g.grid.geometry.attributes.position.needsUpdate = true;
    }
  }

  /** Zone points drawn at the time shown, over every multi-zone sensor (for tests). */
  pointsShown() {
    return this.grids.reduce((n, g) => n + g.shown, 0);
  }
}
