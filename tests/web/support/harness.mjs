// What a browser test of web/ needs: a real facewire-server on a free
// loopback port with a data directory of its own, and Debian's Chromium
// driven by playwright-core (WebGL2 on SwiftShader, no GPU), both shut down
// at the end. FW_BIN_DIR and FW_SOURCE_DIR come from ctest
// (tests/web/CMakeLists.txt).
import { spawn, execFile } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createInterface } from 'node:readline';

export const CHROMIUM = '/usr/bin/chromium';

// SwiftShader for WebGL2 (no GPU), and nothing that reaches for the network:
// the test machines have none, and Chromium would otherwise keep trying.
const CHROMIUM_ARGS = [
  '--no-sandbox', '--no-first-run', '--disable-quic', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
];

function required(variable) {
  const value = process.env[variable];
  if (!value) throw new Error(`${variable} is not set: run the browser tests through ctest (ctest -L web)`);
  return value;
}

/// The path of a built program, e.g. program('facewire-server').
export function program(name) {
  return join(required('FW_BIN_DIR'), name);
}

/// A file of the source tree, e.g. sourceFile('tests/data/astronaut.png').
export function sourceFile(relative) {
  return join(required('FW_SOURCE_DIR'), relative);
}

/// Runs a built program to its end; resolves with { stdout, stderr }.
export function runProgram(name, args) {
  return new Promise((resolve, reject) => {
    execFile(program(name), args, { timeout: 20000 }, (error, stdout, stderr) => {
      if (error) reject(new Error(`${name} ${args.join(' ')}: ${error.message}\n${stderr}`));
      else resolve({ stdout, stderr });
    });
  });
}

/// What one address may do, raised: every page and client of a test runs on 127.0.0.1.
const ONE_ADDRESS_LIMITS = ['--joins-per-minute', '100000', '--room-joins-per-minute', '100000', '--rooms-per-hour', '100000', '--chat-per-minute', '100000',
  '--seats-per-address', '64', '--seats-per-block', '64', '--rooms-per-address', '100000', '--rooms-per-block', '100000'];

/// Starts `facewire-server serve` on 127.0.0.1:0 with `args`; resolves with
/// { url, port, dataDir, log(), stop() } once it prints its address.
export async function startServer(args = []) {
  const dataDir = mkdtempSync(join(tmpdir(), 'facewire-web-test-'));
  const child = spawn(program('facewire-server'),
    ['serve', '--http', '127.0.0.1:0', '--data', dataDir, ...ONE_ADDRESS_LIMITS, ...args],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  let stderr = '';
  child.stderr.on('data', (chunk) => { stderr = (stderr + chunk).slice(-20000); });
  // Never outlive the test process, even when it fails.
  const kill = () => child.kill('SIGKILL');
  process.on('exit', kill);

  const firstLine = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`facewire-server did not start within 30 s:\n${stderr}`)), 30000);
    child.once('exit', (code) => reject(new Error(`facewire-server exited with ${code}:\n${stderr}`)));
    createInterface({ input: child.stdout }).once('line', (line) => { clearTimeout(timer); resolve(line); });
  });
  const match = /(http:\/\/127\.0\.0\.1:(\d+))\/?$/.exec(firstLine);
  if (!match) throw new Error(`facewire-server printed '${firstLine}', not its address`);
  return {
    url: `${match[1]}/`,
    port: Number(match[2]),
    dataDir,
    log: () => stderr,
    /** kill -9, as a server that dies; stop() still removes its data. */
    async kill() {
      if (child.exitCode !== null || child.signalCode !== null) return;
      const exited = new Promise((resolve) => child.once('exit', resolve));
      kill();
      await exited;
    },
    async stop() {
      process.off('exit', kill);
      if (child.exitCode === null && child.signalCode === null) {
        const exited = new Promise((resolve) => child.once('exit', resolve));
        child.kill('SIGTERM');
        const late = setTimeout(kill, 5000);
        await exited;
        clearTimeout(late);
      }
      rmSync(dataDir, { recursive: true, force: true });
    },
  };
}

/// Launches headless Chromium through playwright-core, with `extraArgs`
/// besides the usual ones (a fake camera, say).
export async function launchBrowser(extraArgs = []) {
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch {
    throw new Error('playwright-core is not installed: run `make test`, or `npm ci` in tests/web');
  }
  return chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS, ...extraArgs], timeout: 30000 });
}

/// A server and a browser for one test file: `const env = await openWeb()`,
/// then `env.page(viewport)` for a fresh page and `env.close()` at the end.
/// Errors the pages throw are collected in env.pageErrors.
export async function openWeb(serverArgs = [], { browserArgs = [] } = {}) {
  const server = await startServer(serverArgs);
  let browser;
  try {
    browser = await launchBrowser(browserArgs);
  } catch (error) {
    await server.stop();
    throw error;
  }
  const pageErrors = [];
  return {
    server,
    browser,
    pageErrors,
    async page(viewport = { width: 1280, height: 800 }) {
      const context = await browser.newContext({ viewport });
      const page = await context.newPage();
      page.on('pageerror', (error) => pageErrors.push(error.message));
      page.setDefaultTimeout(20000);
      return page;
    },
    async close() {
      await browser.close().catch(() => {});
      await server.stop();
    },
  };
}
