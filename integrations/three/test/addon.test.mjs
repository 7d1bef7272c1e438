// The add-on's switching, without a GPU: which materials a mesh gets, what their shaders hold,
// and the errors for what it cannot do.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import {COR_ATTRIBUTE, setSkinningMethod, skinningMethodOf} from '../src/index.js';
import {skinningVertexShader} from '../src/shader.js';

function skinnedMesh(withCentres) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute([0, 0, 0, 0, 1, 0, 1, 0, 0], 3));
    geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute([0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0], 4));
    geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute([0.5, 0.5, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0], 4));
    if (withCentres) {
        geometry.setAttribute(COR_ATTRIBUTE, new THREE.Float32BufferAttribute([0, 0.5, 0, 0, 1, 0, 0, 0, 0], 3));
    }
    const root = new THREE.Bone();
    const child = new THREE.Bone();
    child.position.y = 1;
    root.add(child);
    const mesh = new THREE.SkinnedMesh(geometry, new THREE.MeshStandardMaterial({color: 0x808080}));
    mesh.name = withCentres ? 'with' : 'without';
    mesh.add(root);
    mesh.bind(new THREE.Skeleton([root, child]));
    return mesh;
}

test('dqs and cor give the mesh a copy of its material per method; lbs gives back its own', () => {
    const mesh = skinnedMesh(true);
    const original = mesh.material;
    assert.equal(setSkinningMethod(mesh, 'dqs'), 1);
    const dqs = mesh.material;
    assert.notEqual(dqs, original);
    assert.equal(dqs.type, original.type);
    assert.equal(dqs.color.getHex(), 0x808080);
    assert.equal(dqs.customProgramCacheKey(), 'skinlab-dqs-4');
    assert.equal(skinningMethodOf(mesh), 'dqs');
    setSkinningMethod(mesh, 'cor');
    assert.equal(mesh.material.customProgramCacheKey(), 'skinlab-cor-4');
    setSkinningMethod(mesh, 'lbs');
    assert.equal(mesh.material, original);
    setSkinningMethod(mesh, 'dqs');
    assert.equal(mesh.material, dqs, 'each method\'s material is made once');
});

test('the method material\'s shader replaces three\'s skinning chunks and nothing else', () => {
    const mesh = skinnedMesh(true);
    setSkinningMethod(mesh, 'cor');
    const shader = {vertexShader: THREE.ShaderLib.physical.vertexShader, fragmentShader: '', uniforms: {}};
    mesh.material.onBeforeCompile(shader);
    for (const chunk of ['skinbase_vertex', 'skinnormal_vertex', 'skinning_vertex']) {
        assert.ok(!shader.vertexShader.includes(`#include <${chunk}>`), chunk);
    }
    for (const chunk of ['morphtarget_vertex', 'project_vertex', 'skinning_pars_vertex', 'normal_vertex']) {
        assert.ok(shader.vertexShader.includes(`#include <${chunk}>`), chunk);
    }
    assert.match(shader.vertexShader, /in vec3 _cor_center;/);
    assert.match(shader.vertexShader, /cor\(transformed, vec3\(0\.0, 0\.0, 1\.0\), _cor_center, skinlabP, skinlabN\);/);
    assert.ok(shader.uniforms.skinlabPalette.value.isDataTexture);
    assert.deepEqual(Object.keys(shader.uniforms).sort(), ['skinlabPalette', 'uHasScale', 'uMatricesMirror',
        'uScalesMirror']);
});

test('cor without _COR_CENTER is refused, naming the mesh, and switches nothing', () => {
    const group = new THREE.Group();
    const a = skinnedMesh(true);
    const b = skinnedMesh(false);
    group.add(a, b);
    const before = a.material;
    assert.throws(() => setSkinningMethod(group, 'cor'), /_COR_CENTER.*'without'.*skinlab export/);
    assert.equal(a.material, before);
    assert.throws(() => setSkinningMethod(group, 'bfdqs'), /unknown skinning method 'bfdqs'/);
});

test('a geometry with JOINTS_1/WEIGHTS_1 is skinned with 8 influence slots', () => {
    const mesh = skinnedMesh(false);
    mesh.geometry.setAttribute('joints_1', new THREE.Uint16BufferAttribute(new Array(12).fill(0), 4));
    mesh.geometry.setAttribute('weights_1', new THREE.Float32BufferAttribute(new Array(12).fill(0), 4));
    setSkinningMethod(mesh, 'dqs');
    assert.equal(mesh.material.customProgramCacheKey(), 'skinlab-dqs-8');
});

test('a shader without three\'s skinning chunks is refused', () => {
    assert.throws(() => skinningVertexShader('void main() {}', 'dqs', 4), /no #include <skinning_pars_vertex>/);
});
