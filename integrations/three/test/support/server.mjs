// A static http server on 127.0.0.1 for the headless pages: the package's own files (pages,
// src, node_modules/three) and named extra files (the model under test), nothing from the
// network.
import {createServer} from 'node:http';
import {readFile} from 'node:fs/promises';
import {extname, join, normalize, sep} from 'node:path';

const TYPES = {
    '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
    '.glb': 'model/gltf-binary', '.gltf': 'model/gltf+json', '.bin': 'application/octet-stream', '.png': 'image/png',
};

/**
 * Serves {@code root} and the {@code extra} files (url path -> file path) until closed.
 *
 * @returns {Promise<{url: string, close: () => Promise<void>}>}
 */
export async function serve(root, extra = {}) {
    const server = createServer(async (request, response) => {
        const path = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
        let file = extra[path];
        if (!file) {
            file = normalize(join(root, path));
            if (!file.startsWith(normalize(root) + sep)) {
                response.writeHead(403).end();
                return;
            }
        }
        try {
            const body = await readFile(file);
            response.writeHead(200, {'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream'}).end(body);
        } catch {
            response.writeHead(404).end('not found: ' + path);
        }
    });
    await new Promise(resolve => server.listen(0, '127.0.0.1', resolve));
    return {
        url: `http://127.0.0.1:${server.address().port}`,
        close: () => new Promise(resolve => server.close(() => resolve())),
    };
}
