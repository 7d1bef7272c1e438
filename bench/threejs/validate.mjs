// Runs the Khronos glTF-Validator (npm gltf-validator) over .gltf/.glb files and prints one line per
// file: errors, warnings, infos, hints and the first few messages. Exit status 1 when any file has
// an error (or cannot be read), so scripts can require valid files.
//
//   node validate.mjs FILE...            external resources are read from the file's folder
//   node validate.mjs --json FILE...     one JSON line per file: the validator's issues summary
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

const args = process.argv.slice(2);
const json = args[0] === '--json';
const files = json ? args.slice(1) : args;
if (files.length === 0) {
    console.error('usage: node validate.mjs [--json] FILE...');
    process.exit(2);
}

async function validate(file) {
    const bytes = new Uint8Array(await readFile(file));
    const folder = path.dirname(file);
    return validator.validateBytes(bytes, {
        uri: path.basename(file),
        maxIssues: 0,
        externalResourceFunction: (uri) => {
            const target = path.resolve(folder, decodeURIComponent(uri));
            if (!target.startsWith(path.resolve(folder) + path.sep)) {
                return Promise.reject(new Error(`${uri}: outside the file's folder`));
            }
            return readFile(target).then((b) => new Uint8Array(b));
        },
    });
}

let failed = 0;
for (const file of files) {
    try {
        const report = await validate(file);
        const issues = report.issues;
        if (issues.numErrors > 0) {
            failed++;
        }
        if (json) {
            console.log(JSON.stringify({ file, errors: issues.numErrors, warnings: issues.numWarnings,
                infos: issues.numInfos, hints: issues.numHints,
                messages: issues.messages.map((m) => `${m.severity} ${m.code} ${m.pointer ?? ''} ${m.message}`) }));
        } else {
            console.log(`${path.basename(file)}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, `
                + `${issues.numInfos} infos, ${issues.numHints} hints`);
            for (const m of issues.messages.filter((x) => x.severity <= 1).slice(0, 8)) {
                console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
            }
        }
    } catch (e) {
        failed++;
        console.log(`${path.basename(file)}: cannot validate: ${e.message ?? e}`);
    }
}
process.exit(failed > 0 ? 1 : 0);
