// What a person reads when an upload fails.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { retryAfterSeconds, uploadErrorMessage } from '../../../web/lobby/upload_errors.js';

test('the server\'s own words are shown for 413, 415, 422 and 503', () => {
  for (const status of [413, 415, 422, 503]) {
    assert.equal(uploadErrorMessage(status, 'what the server said\n', null), 'what the server said', String(status));
  }
});

test('without words, each status still says what to do', () => {
  assert.match(uploadErrorMessage(413, '', null), /smaller photo/);
  assert.match(uploadErrorMessage(415, '', null), /JPEG, PNG or WebP/);
  assert.match(uploadErrorMessage(422, '', null), /another photo/);
  assert.match(uploadErrorMessage(0, '', null), /did not reach the server/);
  assert.match(uploadErrorMessage(500, '', null), /HTTP 500/);
});

test('a 429 says when to try again, from Retry-After', () => {
  assert.match(uploadErrorMessage(429, 'at most 6 uploads a minute', '37'), /try again in 37 seconds/);
  assert.match(uploadErrorMessage(429, '', '1'), /try again in a second/);
  assert.match(uploadErrorMessage(429, '', '300'), /try again in 5 minutes/);
  assert.match(uploadErrorMessage(429, '', null), /try again in a minute/);
});

test('Retry-After in seconds or as an HTTP date', () => {
  assert.equal(retryAfterSeconds('12'), 12);
  const now = Date.parse('2025-01-01T00:00:00Z');
  assert.equal(retryAfterSeconds('Wed, 01 Jan 2025 00:00:30 GMT', now), 30);
  assert.equal(retryAfterSeconds('soon'), null);
  assert.equal(retryAfterSeconds(null), null);
});
