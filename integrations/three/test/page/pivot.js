// A hand-made case for the DQS pivot: one vertex on three joints turned 0, 100 and 200 degrees
// about Z, weights 0.2, 0.5, 0.3 in that slot order (slot 0 not the heaviest). Only the heaviest
// (100 degrees) as pivot keeps all three rotations on one side: the lightest (0 degrees) as pivot
// would flip the 200 degree one (their quaternions' dot is cos(100 degrees) < 0) and turn the
// vertex elsewhere. Returns the vertex's world position read back from the GPU.
import * as THREE from 'three';
import {setSkinningMethod} from '../../src/index.js';
import {captureContext, withCapture} from './capture.js';

export function pivotCase(method, point, anglesDegrees, weights) {
    const context = captureContext();
    const renderer = new THREE.WebGLRenderer({canvas: context.canvas, context: context.gl});
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(point, 3));
    geometry.setAttribute('normal', new THREE.Float32BufferAttribute([0, 0, 1], 3));
    geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute([0, 1, 2, 0], 4));
    geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute([...weights, 0], 4));
    // CoR's centre at the origin, which every turn fixes: CoR's result is then DQS's rotation of the point.
    geometry.setAttribute('_cor_center', new THREE.Float32BufferAttribute([0, 0, 0], 3));
    const scene = new THREE.Scene();
    const bones = anglesDegrees.map(a => {
        const bone = new THREE.Bone();
        bone.quaternion.setFromAxisAngle(new THREE.Vector3(0, 0, 1), a * Math.PI / 180);
        scene.add(bone);
        return bone;
    });
    const mesh = new THREE.SkinnedMesh(geometry, new THREE.MeshStandardMaterial());
    mesh.frustumCulled = false;
    scene.add(mesh);
    scene.updateMatrixWorld(true);
    // Bound at rest: the inverse bind matrices are the identity, the bones' turns are the pose.
    mesh.bind(new THREE.Skeleton(bones, bones.map(() => new THREE.Matrix4())), new THREE.Matrix4());
    setSkinningMethod(mesh, method);
    withCapture(mesh.material);
    const camera = new THREE.PerspectiveCamera();
    return [...context.capture(1, () => renderer.render(mesh, camera))];
}

/**
 * A mesh bound where it stands, away from the origin and turned (three's SkinnedMesh.bind with
 * its world matrix, so bindMatrix is not the identity), its one bone then turned and moved: every
 * vertex on that one joint moves rigidly, so LBS, DQS and CoR must put it at the same place.
 * Returns the world positions of the given points under {@code method}.
 */
export function boundAwayCase(method, points) {
    const context = captureContext();
    const renderer = new THREE.WebGLRenderer({canvas: context.canvas, context: context.gl});
    const count = points.length / 3;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
    geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(new Array(4 * count).fill(0), 4));
    geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(
        Array.from({length: 4 * count}, (_, i) => (i % 4 === 0 ? 1 : 0)), 4));
    geometry.setAttribute('_cor_center', new THREE.Float32BufferAttribute(new Array(3 * count).fill(0.25), 3));
    const scene = new THREE.Scene();
    const bone = new THREE.Bone();
    bone.position.set(0.5, 1, -0.3);
    scene.add(bone);
    const mesh = new THREE.SkinnedMesh(geometry, new THREE.MeshStandardMaterial());
    mesh.frustumCulled = false;
    mesh.position.set(2, -1, 0.5);
    mesh.quaternion.setFromAxisAngle(new THREE.Vector3(1, 1, 0).normalize(), 0.7);
    scene.add(mesh);
    scene.updateMatrixWorld(true);
    mesh.bind(new THREE.Skeleton([bone]));
    bone.quaternion.setFromAxisAngle(new THREE.Vector3(0.2, 1, 0.4).normalize(), 1.9);
    bone.position.set(-0.4, 0.3, 1.1);
    scene.updateMatrixWorld(true);
    setSkinningMethod(mesh, method);
    withCapture(mesh.material);
    const camera = new THREE.PerspectiveCamera();
    return [...context.capture(count, () => renderer.render(mesh, camera))];
}
