// The lobby's languages (web/lobby/languages.js): the server's list as it
// comes from GET /api/languages, read defensively, and which one is chosen.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { DEFAULT_LANGUAGE, chooseLanguage, fetchLanguages, parseLanguages } from '../../../web/lobby/languages.js';

const list = { default: 'en', languages: [{ code: 'de', name: 'German' }, { code: 'en', name: 'English' }, { code: 'pt-br', name: 'Portuguese (Brazil)' }] };

test('the server\'s list is read as it comes', async () => {
  const fetcher = async (url) => {
    assert.equal(url, 'api/languages');
    return { ok: true, json: async () => list };
  };
  assert.deepEqual(await fetchLanguages(fetcher), list);
});

test('a refusal says what failed', async () => {
  await assert.rejects(fetchLanguages(async () => ({ ok: false, status: 404 })), /unavailable \(HTTP 404\)/);
});

test('entries without a language code are left out; a default it does not list falls back', () => {
  const parsed = parseLanguages({
    default: 'xx',
    languages: [{ code: 'EN', name: 'shouting' }, { code: 'de' }, { code: '../x', name: 'x' }, null, { code: 'en', name: 'English' }],
  });
  assert.deepEqual(parsed, { default: 'en', languages: [{ code: 'de', name: 'de' }, { code: 'en', name: 'English' }] });
  assert.deepEqual(parseLanguages(null), { default: DEFAULT_LANGUAGE, languages: [] });
});

test('the kept choice when the server speaks it, else the server\'s default', () => {
  assert.equal(chooseLanguage('de', list), 'de');
  assert.equal(chooseLanguage('fr', list), 'en');
  assert.equal(chooseLanguage('', list), 'en');
});
