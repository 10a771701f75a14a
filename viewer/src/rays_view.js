// Each sensor's ray at the sample shown: a thick segment from the sensor's
// origin to its hit point (or origin + d_max·dir), coloured by the reading's
// status, with a dot at its end. Buffers are allocated once and rewritten in
// place every frame.
import * as THREE from 'three';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { sampleAt } from './timeline.js';

export class RaysView {
  constructor(scene, sensors, statusColors) {
    this.sensors = sensors;
    this.statusRgb = statusColors.map((c) => new THREE.Color(c));
    const n = Math.max(sensors.length, 1);
    this.segments = new Float32Array(6 * n);
    this.colors = new Float32Array(6 * n);
    this.ends = new Float32Array(3 * n);
    this.endColors = new Float32Array(3 * n);

    this.geometry = new LineSegmentsGeometry();
    this.geometry.setPositions(this.segments);
    this.geometry.setColors(this.colors);
    this.material = new LineMaterial({ linewidth: 3, vertexColors: true, worldUnits: false });
    this.lines = new LineSegments2(this.geometry, this.material);
    this.lines.frustumCulled = false;
    scene.add(this.lines);

    const dots = new THREE.BufferGeometry();
    dots.setAttribute('position', new THREE.BufferAttribute(this.ends, 3));
    dots.setAttribute('color', new THREE.BufferAttribute(this.endColors, 3));
    this.dots = new THREE.Points(dots, new THREE.PointsMaterial({ size: 9, sizeAttenuation: false, vertexColors: true }));
    this.dots.frustumCulled = false;
    scene.add(this.dots);
  }

  /** Rewrites the rays for time t; sensors whose `visible[i]` is false collapse to nothing. */
  update(t, visible) {
    this.sensors.forEach((s, j) => {
      const i = sampleAt(s.t, t);
      const seg = this.segments;
      for (let a = 0; a < 3; a++) {
        const o = s.origin[3 * i + a];
        seg[6 * j + a] = o;
        seg[6 * j + 3 + a] = visible[j] ? s.end[3 * i + a] : o;
        this.ends[3 * j + a] = visible[j] ? s.end[3 * i + a] : NaN;
      }
      const c = this.statusRgb[s.status[i]] || this.statusRgb[1];
      for (const k of [6 * j, 6 * j + 3]) {
        this.colors[k] = c.r; this.colors[k + 1] = c.g; this.colors[k + 2] = c.b;
      }
      this.endColors[3 * j] = c.r; this.endColors[3 * j + 1] = c.g; this.endColors[3 * j + 2] = c.b;
    });
    this.geometry.attributes.instanceStart.data.needsUpdate = true;
    this.geometry.attributes.instanceColorStart.data.needsUpdate = true;
    this.dots.geometry.attributes.position.needsUpdate = true;
    this.dots.geometry.attributes.color.needsUpdate = true;
  }

  /** Flat [ox, oy, oz, ex, ey, ez] per sensor as shown (for tests). */
  endpoints() {
    return Array.from(this.segments);
  }

  resize(size) {
    this.material.resolution.copy(size);
  }
}
