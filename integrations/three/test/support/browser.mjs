// Headless Chromium with WebGL2 on the CPU (SwiftShader through ANGLE), so that the pages run
// on machines without a GPU, CI's included. The browser is the system's (Debian's chromium):
// puppeteer-core downloads none. CHROMIUM names another executable.
import {existsSync} from 'node:fs';
import puppeteer from 'puppeteer-core';

export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

/** Whether the browser executable exists. */
export function chromiumAvailable() {
    return existsSync(CHROMIUM);
}

/**
 * Starts the browser.
 *
 * @returns {Promise<import('puppeteer-core').Browser>}
 * @throws {Error} naming the executable when it is missing
 */
export async function launch() {
    if (!chromiumAvailable()) {
        throw new Error(`no Chromium at ${CHROMIUM} (apt-get install chromium, or set CHROMIUM to its executable)`);
    }
    return puppeteer.launch({
        executablePath: CHROMIUM,
        headless: true,
        args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
            '--disable-dev-shm-usage'],
    });
}

/** A new page whose console errors and uncaught exceptions go to stderr. */
export async function newPage(browser) {
    const page = await browser.newPage();
    page.on('console', m => {
        if (m.type() === 'error' || m.type() === 'warn') {
            process.stderr.write(`[page ${m.type()}] ${m.text()}\n`);
        }
    });
    page.on('pageerror', e => process.stderr.write(`[page error] ${e.message}\n`));
    return page;
}
