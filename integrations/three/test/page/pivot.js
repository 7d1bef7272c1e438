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
