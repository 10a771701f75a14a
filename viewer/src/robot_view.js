// The robot: one group per link (its shapes placed relative to the link), moved
// to the link's recorded world pose at the sample shown.
import * as THREE from 'three';
import { shapeMesh } from './shapes.js';
import { sampleAt } from './timeline.js';

export class RobotView {
  /** robot: scene.json's robot (or null); poses: {t, links: {name: flat [x,y,z,qw,qx,qy,qz]*N}}. */
  constructor(scene, robot, poses) {
    this.poses = poses;
    this.links = new Map();
    if (!robot || !poses) return;
    const material = new THREE.MeshLambertMaterial({ color: 0x4f6d8f });
    const joint = new THREE.MeshLambertMaterial({ color: 0x2f3f52 });
    // a link that has collided, from its collision on (sim/contacts.h, docs/outcomes.md)
    this.struck = new THREE.MeshLambertMaterial({ color: 0xd62728, emissive: 0x5a0000 });
    this.struckSince = new Map();
    for (const link of robot.links) {
      const group = new THREE.Group();
      group.name = link.name;
      for (const shape of link.shapes || []) {
        const mesh = shapeMesh(shape, shape.shape === 'sphere' ? joint : material);
        if (mesh) group.add(mesh);
      }
      group.visible = Boolean(poses.links[link.name]);
      for (const mesh of group.children) mesh.userData.material = mesh.material;
      scene.add(group);
      this.links.set(link.name, group);
    }
  }

  /** collisions: data.collisions ([{t, link, p}]): each link is drawn red from its first one on. */
  markCollisions(collisions) {
    for (const c of collisions || []) {
      if (!this.struckSince.has(c.link) || c.t < this.struckSince.get(c.link)) this.struckSince.set(c.link, c.t);
    }
  }

  /** Names of the links drawn as collided at the time last shown. */
  struckLinks() {
    return [...this.links].filter(([, g]) => g.children.some((m) => m.material === this.struck)).map(([n]) => n);
  }

  /** Poses every link at time t (the last sample at or before t). */
  update(t) {
    if (!this.poses) return;
    const i = sampleAt(this.poses.t, t);
    for (const [name, group] of this.links) {
      const since = this.struckSince.get(name);
      const struck = since !== undefined && since <= t;
      for (const mesh of group.children) mesh.material = struck ? this.struck : mesh.userData.material;
      const p = this.poses.links[name];
      if (!p) continue;
      const k = 7 * i;
      group.position.set(p[k], p[k + 1], p[k + 2]);
      group.quaternion.set(p[k + 4], p[k + 5], p[k + 6], p[k + 3]).normalize();
    }
  }

  /** World position [x, y, z] of a link as shown, or null for an unknown link. */
  linkPosition(name) {
    const group = this.links.get(name);
    return group ? group.position.toArray() : null;
  }

  /** The link that carries the robot (pelvis, base…), to follow with the camera. */
  rootLink() {
    for (const name of ['pelvis', 'base_link', 'base', 'torso']) {
      if (this.links.has(name)) return this.links.get(name);
    }
    return this.links.values().next().value || null;
  }
}
