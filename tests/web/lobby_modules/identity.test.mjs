// The name and avatar kept across reloads, and a storage that fails.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { loadIdentity, saveIdentity } from '../../../web/lobby/identity.js';

function memoryStorage() {
  const items = new Map();
  return { getItem: (k) => items.get(k) ?? null, setItem: (k, v) => items.set(k, String(v)) };
}

test('what is saved is loaded', () => {
  const storage = memoryStorage();
  assert.deepEqual(loadIdentity(storage), { name: '', asset: '', key: '', language: '' });
  saveIdentity({ name: 'Ann', asset: 'ab'.repeat(16), key: 'k3y' }, storage);
  assert.deepEqual(loadIdentity(storage), { name: 'Ann', asset: 'ab'.repeat(16), key: 'k3y', language: '' });
});

test('an avatar saved without its key is forgotten: it could not be worn', () => {
  const storage = memoryStorage();
  saveIdentity({ name: 'Ann', asset: 'ab'.repeat(16), key: '' }, storage);
  assert.deepEqual(loadIdentity(storage), { name: 'Ann', asset: '', key: '', language: '' });
});

test('a broken or refusing storage loses nothing but the memory', () => {
  const broken = { getItem: () => '{not json', setItem: () => { throw new Error('QuotaExceededError'); } };
  assert.deepEqual(loadIdentity(broken), { name: '', asset: '', key: '', language: '' });
  assert.doesNotThrow(() => saveIdentity({ name: 'Ann', asset: '' }, broken));
});

test('the language is kept with the name, and a save that leaves it out keeps it', () => {
  const storage = memoryStorage();
  saveIdentity({ name: 'Ann', asset: '', key: '', language: 'de' }, storage);
  assert.equal(loadIdentity(storage).language, 'de');
  saveIdentity({ name: 'Anna', asset: '', key: '' }, storage);  // typing the name keeps the language
  assert.deepEqual(loadIdentity(storage), { name: 'Anna', asset: '', key: '', language: 'de' });
});
