// The terrain map growing with time: one flat square per measured cell, at
// its height and coloured by it (the report's figure's colour scale), shown
// from the time the cell first held a height (the cells are sorted by that
// time, so a draw range is all that changes); and each hazard the map found,
// marked from the time it was found: its footprint outlined at the map's
// surface there and a pin above its centroid, in its class's colour.
// A cell is drawn with its final fused height, not the height it held at the
// time shown: the run's files keep the map's last state only.
import * as THREE from 'three';
import { countUpTo } from './timeline.js';

// a cell's square sits this far above its height, clear of the surface it maps
const LIFT_M = 0.004;
const PIN_HEIGHT_M = 0.3;

/** The colour of value v on a ramp of evenly spaced stops over [lo, hi]. */
export function rampColor(stops, lo, hi, v, out = new THREE.Color()) {
  const u = Math.min(Math.max((v - lo) / Math.max(hi - lo, 1e-9), 0), 1) * (stops.length - 1);
  const k = Math.min(Math.floor(u), stops.length - 2);
  return out.copy(stops[k]).lerp(stops[k + 1], u - k);
}

export class TerrainView {
  /** terrain: data.terrain (or null: the run has no map). */
  constructor(scene, terrain) {
    this.group = new THREE.Group();
    this.group.name = 'terrain-map';
    scene.add(this.group);
    this.times = terrain ? terrain.t : [];
    this.hazards = [];
    this.mesh = null;
    this.visible = true;
    if (!terrain) return;

    // the cells: two triangles each, in the order they were first measured
    const n = this.times.length;
    const half = terrain.resolution / 2;
    const stops = terrain.colorStops.map((c) => new THREE.Color(c));
    const [lo, hi] = terrain.zRange;
    const positions = new Float32Array(18 * n);
    const colors = new Float32Array(18 * n);
    const corners = [[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]];
    const c = new THREE.Color();
    for (let i = 0; i < n; i += 1) {
      rampColor(stops, lo, hi, terrain.z[i], c);
      corners.forEach(([sx, sy], k) => {
        const o = 18 * i + 3 * k;
        positions[o] = terrain.x[i] + sx * half;
        positions[o + 1] = terrain.y[i] + sy * half;
        positions[o + 2] = terrain.z[i] + LIFT_M;
        colors[o] = c.r; colors[o + 1] = c.g; colors[o + 2] = c.b;
      });
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    geometry.setDrawRange(0, 0);
    this.mesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({
      vertexColors: true, side: THREE.DoubleSide, transparent: true, opacity: 0.9,
      polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -1,
    }));
    this.mesh.frustumCulled = false;
    this.group.add(this.mesh);

    // the hazards: footprint outline and pin
    for (const h of terrain.hazards) {
      const marker = new THREE.Group();
      marker.name = `hazard-${h.class}`;
      const color = new THREE.Color(h.color);
      const z = h.z + 2 * LIFT_M;
      const hx = h.sizeX / 2;
      const hy = h.sizeY / 2;
      const outline = new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(h.x - hx, h.y - hy, z), new THREE.Vector3(h.x + hx, h.y - hy, z),
        new THREE.Vector3(h.x + hx, h.y + hy, z), new THREE.Vector3(h.x - hx, h.y + hy, z)]);
      marker.add(new THREE.LineLoop(outline, new THREE.LineBasicMaterial({ color })));
      const pin = new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(h.x, h.y, z), new THREE.Vector3(h.x, h.y, z + PIN_HEIGHT_M)]);
      marker.add(new THREE.Line(pin, new THREE.LineBasicMaterial({ color })));
      const head = new THREE.Mesh(new THREE.SphereGeometry(0.025, 12, 8), new THREE.MeshLambertMaterial({ color }));
      head.position.set(h.x, h.y, z + PIN_HEIGHT_M);
      marker.add(head);
      marker.userData.t = h.t ?? -Infinity;  // no time known: shown throughout
      marker.visible = false;
      this.group.add(marker);
      this.hazards.push(marker);
    }
  }

  /** Shows the cells measured and the hazards found up to time t. */
  update(t) {
    this.group.visible = this.visible;
    if (this.mesh) this.mesh.geometry.setDrawRange(0, 6 * countUpTo(this.times, t));
    for (const m of this.hazards) m.visible = m.userData.t <= t;
  }

  setVisible(on) { this.visible = on; }

  /** Number of cells drawn (for tests; 0 when the layer is hidden). */
  cellsShown() { return this.visible && this.mesh ? this.mesh.geometry.drawRange.count / 6 : 0; }

  /** Number of hazards marked (for tests). */
  hazardsShown() { return this.visible ? this.hazards.filter((m) => m.visible).length : 0; }
}
