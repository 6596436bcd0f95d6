// web/'s folders import only in the allowed direction (web/README.md,
// "Folders"): a page's folder never imports another page's, the libraries
// never import a page, shared/ imports nothing. And every import, script
// and stylesheet names a file that exists, so a module moved without its
// importers fails here before a browser test does.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const web = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'web');

// What each folder may import besides itself ('' is web/'s root).
const ALLOWED = {
  '': ['lobby', 'room', 'shared'],
  shared: [],
  codec: ['shared'],
  protocol: ['shared'],
  engine: ['shared'],
  speech: ['shared'],
  lobby: ['shared'],
  room: ['shared', 'codec', 'protocol', 'engine', 'speech'],
};

function filesUnder(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    (e.isDirectory() ? filesUnder(join(dir, e.name)) : [join(dir, e.name)]));
}
const folderOf = (file) => {
  const parts = relative(web, file).split(sep);
  return parts.length > 1 ? parts[0] : '';
};
// Files the build adds beside web/'s own (the engine's and the speech's WebAssembly modules).
const BUILT = new Set([join(web, 'engine', 'facewire_model.js'), join(web, 'engine', 'facewire_model.wasm'),
  join(web, 'speech', 'facewire_speech.js'), join(web, 'speech', 'facewire_speech.wasm')]);

const modules = filesUnder(web).filter((f) => f.endsWith('.js') || f.endsWith('.mjs'));
const pages = filesUnder(web).filter((f) => f.endsWith('.html'));

function importsOf(file) {
  const text = readFileSync(file, 'utf8');
  const found = [];
  for (const m of text.matchAll(/^\s*(?:import|export)\s[^;]*?\sfrom\s+'([^']+)'/gms)) found.push(m[1]);
  for (const m of text.matchAll(/^\s*import\s+'([^']+)'/gm)) found.push(m[1]);
  return found.filter((spec) => spec.startsWith('.'));
}

test('there are modules and pages to check', () => {
  assert.ok(modules.length > 40, `${modules.length} modules`);
  assert.ok(pages.length >= 2, `${pages.length} pages`);
});

test('every relative import names a file that exists', () => {
  for (const file of modules) {
    for (const spec of importsOf(file)) {
      const target = resolve(dirname(file), spec);
      assert.ok(existsSync(target) || BUILT.has(target), `${relative(web, file)} imports ${spec}, which is not there`);
    }
  }
});

test('folders import only in the allowed direction', () => {
  let checked = 0;
  for (const file of modules) {
    const from = folderOf(file);
    assert.ok(from in ALLOWED, `${relative(web, file)}: folder '${from}' is not in web/README.md's map`);
    for (const spec of importsOf(file)) {
      const to = folderOf(resolve(dirname(file), spec));
      if (to === from) continue;
      assert.ok(ALLOWED[from].includes(to), `${relative(web, file)} (${from || 'web/'}) imports ${spec} (${to || 'web/'})`);
      ++checked;
    }
  }
  assert.ok(checked > 10, `only ${checked} imports across folders`);
});

test("the pages' scripts and stylesheets exist", () => {
  for (const page of pages) {
    const text = readFileSync(page, 'utf8');
    const refs = [...text.matchAll(/<script[^>]*\ssrc="([^"]+)"/g), ...text.matchAll(/<link[^>]*rel="stylesheet"[^>]*href="([^"]+)"/g)]
      .map((m) => m[1]);
    assert.ok(refs.length >= 2, `${relative(web, page)}: ${refs.length} scripts and stylesheets`);
    for (const ref of refs) assert.ok(existsSync(resolve(dirname(page), ref)), `${relative(web, page)} loads ${ref}, which is not there`);
  }
});
