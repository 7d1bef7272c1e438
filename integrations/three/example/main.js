// The add-on's example: a skinlab-exported glTF (default model.glb beside this page; ?model=URL
// for another) played in a split view, three's LBS on the left and the chosen method on the
// right, both lit and drawn with the file's own material. ?method=dqs|cor picks the right half's
// method, ?time=T freezes the clip at T seconds, ?focus=BONE adds to each half a close-up of that
// bone's joint seen from the side (the screenshot uses all three).
import * as THREE from 'three';
import {GLTFLoader} from 'three/addons/loaders/GLTFLoader.js';
import {OrbitControls} from 'three/addons/controls/OrbitControls.js';
import {setSkinningMethod} from '../src/index.js';

const params = new URLSearchParams(location.search);
const NAMES = {lbs: 'LBS (three.js)', dqs: 'DQS (skinlab)', cor: 'CoR (skinlab)'};
let method = params.get('method') ?? 'cor';
const frozen = params.has('time') ? Number(params.get('time')) : null;
const focusName = params.get('focus');

const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
renderer.setScissorTest(true);
document.body.appendChild(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242b);
scene.add(new THREE.HemisphereLight(0xdde8ff, 0x3a3028, 1.2));
const sun = new THREE.DirectionalLight(0xffffff, 2.2);
sun.position.set(2, 4, 3);
scene.add(sun);
const ground = new THREE.Mesh(new THREE.CircleGeometry(3, 48), new THREE.MeshStandardMaterial({color: 0x3b4048}));
ground.rotation.x = -Math.PI / 2;
scene.add(ground);

const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
const controls = new OrbitControls(camera, renderer.domElement);

const gltf = await new GLTFLoader().loadAsync(params.get('model') ?? 'model.glb');
scene.add(gltf.scene);
const box = new THREE.Box3().setFromObject(gltf.scene);
const centre = box.getCenter(new THREE.Vector3());
const size = box.getSize(new THREE.Vector3()).length();
ground.position.y = box.min.y;
camera.position.copy(centre).add(new THREE.Vector3(0.55, 0.15, 1).multiplyScalar(1.45 * size));
controls.target.copy(centre);
controls.update();

const focus = focusName ? gltf.scene.getObjectByName(focusName) : null;
if (focusName && !focus) {
    throw new Error(`no bone named '${focusName}' in the model`);
}
const closeUp = new THREE.PerspectiveCamera(12, 1, 0.01, 100);
const focusPoint = new THREE.Vector3();

const mixer = new THREE.AnimationMixer(gltf.scene);
if (gltf.animations.length > 0) {
    mixer.clipAction(gltf.animations[0]).play();
    if (frozen !== null) {
        mixer.setTime(frozen);
    }
}

function choose(m) {
    method = m;
    document.getElementById('right').textContent = NAMES[m];
    for (const b of document.querySelectorAll('#ui button')) {
        b.classList.toggle('chosen', b.dataset.method === m);
    }
}
for (const b of document.querySelectorAll('#ui button')) {
    b.addEventListener('click', () => choose(b.dataset.method));
}
choose(method);

const timer = new THREE.Timer();
let frames = 0;
renderer.setAnimationLoop(() => {
    if (frozen === null) {
        timer.update();
        mixer.update(timer.getDelta());
    }
    const w = window.innerWidth / 2;
    const h = window.innerHeight;
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    // Left: three's own skinning; right: the chosen method. The same mesh in the same pose, drawn
    // twice: switching method only swaps the mesh's material.
    if (focus) {
        gltf.scene.updateMatrixWorld(true);
        focus.getWorldPosition(focusPoint);
        closeUp.position.copy(focusPoint).add(new THREE.Vector3(-0.6 * size, 0.05 * size, 0.05 * size));
        closeUp.lookAt(focusPoint);
    }
    const inset = Math.round(0.42 * w);
    [['lbs', 0], [method, w]].forEach(([m, x]) => {
        setSkinningMethod(gltf.scene, m);
        renderer.setViewport(x, 0, w, h);
        renderer.setScissor(x, 0, w, h);
        renderer.render(scene, camera);
        if (focus) {
            // The close-up in the half's top right corner, framed by a thin border.
            const y = h - inset - 50;
            const left = x + w - inset - 12;
            renderer.setScissor(left - 2, y - 2, inset + 4, inset + 4);
            renderer.setClearColor(0x9aa4b0);
            renderer.clear();
            renderer.setViewport(left, y, inset, inset);
            renderer.setScissor(left, y, inset, inset);
            renderer.render(scene, closeUp);
        }
    });
    if (++frames === 3) {
        window.exampleReady = true;
    }
});

window.addEventListener('resize', () => renderer.setSize(window.innerWidth, window.innerHeight));
