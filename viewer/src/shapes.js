// Three.js meshes for the shapes of scene.json (objects and robot link shapes):
// box (full extents), sphere, cylinder (axis = local z), plane (z = 0 of its
// frame, drawn as a large finite square), mesh (vertices + triangles).
import * as THREE from 'three';

const PLANE_SIZE_M = 40;

/** A BufferGeometry for one shape description, or null for an unknown shape. */
export function shapeGeometry(shape) {
  switch (shape.shape) {
    case 'box': {
      const [x, y, z] = shape.size_m;
      return new THREE.BoxGeometry(x, y, z);
    }
    case 'sphere':
      return new THREE.SphereGeometry(shape.radius_m, 28, 18);
    case 'cylinder': {
      // three's cylinder stands on its y axis; ours on z
      const g = new THREE.CylinderGeometry(shape.radius_m, shape.radius_m, shape.length_m, 28);
      g.rotateX(Math.PI / 2);
      return g;
    }
    case 'plane':
      return new THREE.PlaneGeometry(PLANE_SIZE_M, PLANE_SIZE_M);
    case 'mesh': {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute(shape.vertices_m.flat(), 3));
      g.setIndex(shape.triangles.flat());
      g.computeVertexNormals();
      return g;
    }
    default:
      return null;
  }
}

/** Sets an Object3D's pose from xyz_m and quat_wxyz (missing fields: identity). */
export function applyPose(object, shape) {
  const p = shape.xyz_m || [0, 0, 0];
  const q = shape.quat_wxyz || [1, 0, 0, 0];
  object.position.set(p[0], p[1], p[2]);
  object.quaternion.set(q[1], q[2], q[3], q[0]).normalize();
}

/** A posed mesh for a shape, or null for an unknown shape. */
export function shapeMesh(shape, material) {
  const geometry = shapeGeometry(shape);
  if (!geometry) return null;
  const mesh = new THREE.Mesh(geometry, material);
  applyPose(mesh, shape);
  return mesh;
}
