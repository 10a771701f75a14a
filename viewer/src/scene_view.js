// The 3D stage: renderer, z-up camera with orbit controls, lights, and the
// scene's objects (floor with a grid; walls see-through so that the robot
// stays visible from any side).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { shapeMesh } from './shapes.js';
import { sampleAt } from './timeline.js';

/** A box at least this tall and this long is a wall: drawn see-through. */
const WALL_HEIGHT_M = 1.0;
const WALL_LENGTH_M = 1.5;

function isWall(object) {
  if (object.shape !== 'box') return false;
  const [x, y, z] = object.size_m;
  return z >= WALL_HEIGHT_M && Math.max(x, y) >= WALL_LENGTH_M;
}

function objectMaterial(object) {
  // neutral tones from the albedo, so that the coloured profile points stand out
  const a = Math.min(Math.max(object.albedo ?? 0.6, 0.05), 1);
  const color = new THREE.Color().setRGB(0.55 + 0.35 * a, 0.52 + 0.33 * a, 0.47 + 0.3 * a);
  if (object.shape === 'plane') {
    return new THREE.MeshLambertMaterial({ color: 0xd9d6cf, side: THREE.DoubleSide });
  }
  if (isWall(object)) {
    return new THREE.MeshLambertMaterial({
      color, transparent: true, opacity: 0.16, depthWrite: false, side: THREE.DoubleSide,
    });
  }
  return new THREE.MeshLambertMaterial({ color });
}

export class SceneView {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(0xf4f6f9);
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.02, 200);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8170, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(-3, -4, 8);
    this.scene.add(sun);
    this.resize();
  }

  /** Adds the scene.json objects; returns their bounding box (planes excluded). */
  addObjects(objects) {
    const box = new THREE.Box3();
    this.objectMeshes = new Map();
    for (const object of objects) {
      const mesh = shapeMesh(object, objectMaterial(object));
      if (!mesh) continue;
      mesh.name = object.name;
      this.objectMeshes.set(object.name, mesh);
      if (isWall(object)) mesh.renderOrder = 2;
      this.scene.add(mesh);
      if (object.shape === 'plane') {
        // a metre grid on the floor, slightly above it, for depth
        const grid = new THREE.GridHelper(40, 40, 0x8f8a80, 0xa9a499);
        grid.rotateX(Math.PI / 2);
        grid.position.z = 0.002;
        mesh.add(grid);
      } else {
        box.expandByObject(mesh);
      }
    }
    return box;
  }

  /** Moves the scene's moving objects to their recorded poses at time t
   *  (objectPoses: data.objectPoses, {t, objects: {name: flat [x,y,z,qw,qx,qy,qz]*N}}, or null). */
  moveObjects(objectPoses, t) {
    if (!objectPoses) return;
    const i = sampleAt(objectPoses.t, t);
    for (const [name, p] of Object.entries(objectPoses.objects)) {
      const mesh = this.objectMeshes.get(name);
      if (!mesh) continue;
      const k = 7 * i;
      mesh.position.set(p[k], p[k + 1], p[k + 2]);
      mesh.quaternion.set(p[k + 4], p[k + 5], p[k + 6], p[k + 3]).normalize();
    }
  }

  /** World position [x, y, z] of a scene object as shown, or null (for tests). */
  objectPosition(name) {
    const mesh = this.objectMeshes ? this.objectMeshes.get(name) : null;
    return mesh ? mesh.position.toArray() : null;
  }

  /** Places the camera to look at `target` from behind and to the robot's left
   *  (+y in REP-103, the side of the default run's left-tibia sensors), at `distance`. */
  frame(target, distance) {
    this.controls.target.copy(target);
    this.camera.position.set(target.x - 0.55 * distance, target.y + 0.8 * distance, target.z + 0.45 * distance);
    this.controls.update();
  }

  /** Moves camera and target together (follow mode). */
  translate(delta) {
    this.camera.position.add(delta);
    this.controls.target.add(delta);
  }

  resize() {
    const w = Math.max(this.container.clientWidth, 1);
    const h = Math.max(this.container.clientHeight, 1);
    this.renderer.setSize(w, h, true);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.size = new THREE.Vector2(w, h);
  }

  render() {
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
  }
}
