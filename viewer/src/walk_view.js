// The walk: the path the robot's root link has walked up to the time shown,
// drawn on the floor, and a marker where the robot was at each strategy event
// (obstacle seen, detour planned, stopped…), shown once its time has come.
import * as THREE from 'three';
import { sampleAt } from './timeline.js';

const EVENT_COLORS = { obstacle_seen: 0xe67e22, obstacle_ahead: 0xe67e22, detour_planned: 0x2e86c1,
  detour_replanned: 0x85c1e9, obstacle_passed: 0x27ae60, rejoined: 0x27ae60, goal_reached: 0x1e8449,
  stopped: 0xc0392b, blocked: 0xc0392b, no_way_around: 0xc0392b, collision: 0xd62728, fall: 0x8e44ad,
  cannot_step: 0x8e44ad };

export class WalkView {
  /** poses: data.poses (or null); root: the root link's name; events: data.events;
   *  collisions: data.collisions (a red ball at each contact point, from its time);
   *  fall: data.fall ({t, p}: the fall's marker stands where the foot landed, when p is known). */
  constructor(scene, poses, root, events, collisions, fall) {
    this.times = poses ? poses.t : [];
    this.line = null;
    this.markers = [];
    this.contacts = [];
    const p = poses && root ? poses.links[root] : null;
    if (!p) return;
    // the root's track, just above the floor
    const n = this.times.length;
    const positions = new Float32Array(3 * n);
    for (let i = 0; i < n; i += 1) {
      positions[3 * i] = p[7 * i];
      positions[3 * i + 1] = p[7 * i + 1];
      positions[3 * i + 2] = 0.004;
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    this.line = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: 0x1b4f72 }));
    this.line.name = 'walk-path';
    scene.add(this.line);
    // one marker per event, at the root's place then; a fall's where the foot landed
    for (const e of events || []) {
      const i = sampleAt(this.times, e.t);
      const marker = new THREE.Mesh(new THREE.ConeGeometry(0.03, 0.12, 12),
        new THREE.MeshLambertMaterial({ color: EVENT_COLORS[e.event] ?? 0x7f8c8d }));
      marker.rotation.x = -Math.PI / 2;  // point down onto the floor
      const at = e.event === 'fall' && fall && fall.p ? fall.p : null;
      if (at) marker.position.set(at[0], at[1], at[2] + 0.08);
      else marker.position.set(p[7 * i], p[7 * i + 1], 0.08);
      marker.name = `event-${e.event}`;
      marker.userData.t = e.t;
      scene.add(marker);
      this.markers.push(marker);
    }
    for (const c of collisions || []) {
      const ball = new THREE.Mesh(new THREE.SphereGeometry(0.025, 16, 12),
        new THREE.MeshLambertMaterial({ color: EVENT_COLORS.collision, emissive: 0x5a0000 }));
      ball.position.set(c.p[0], c.p[1], c.p[2]);
      ball.name = `collision-${c.link}`;
      ball.userData.t = c.t;
      scene.add(ball);
      this.contacts.push(ball);
    }
  }

  /** Shows the path and the events up to time t. */
  update(t) {
    if (!this.line) return;
    this.line.geometry.setDrawRange(0, sampleAt(this.times, t) + 1);
    for (const m of [...this.markers, ...this.contacts]) m.visible = m.userData.t <= t;
  }

  /** Number of collision points shown at the current time. */
  collisionsShown() { return this.contacts.filter((m) => m.visible).length; }

  /** Number of events shown at the current time. */
  eventsShown() { return this.markers.filter((m) => m.visible).length; }
}
