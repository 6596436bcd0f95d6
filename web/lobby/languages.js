// The languages this server's faces can speak a line in (GET /api/languages,
// server/PROTOCOL.md 8): the lobby's select, the person's choice kept with
// their name (identity.js), and the room page's address carries it into the
// hello (server/PROTOCOL.md 5.1).

/** The server's default, and what the select holds before the list comes. */
export const DEFAULT_LANGUAGE = 'en';

// A language code as hello carries it: 1 .. 16 of a-z, 0-9 and '-'.
const CODE = /^[a-z0-9-]{1,16}$/;

/**
 * The server's list: { default, languages: [{ code, name }] }, entries
 * without a well-formed code left out.
 */
export async function fetchLanguages(fetcher = globalThis.fetch) {
  const response = await fetcher('api/languages', { cache: 'no-store' });
  if (!response.ok) throw new Error(`the server's languages are unavailable (HTTP ${response.status})`);
  return parseLanguages(await response.json());
}

export function parseLanguages(body) {
  const languages = (Array.isArray(body?.languages) ? body.languages : [])
    .filter((l) => typeof l?.code === 'string' && CODE.test(l.code))
    .map((l) => ({ code: l.code, name: typeof l.name === 'string' && l.name ? l.name : l.code }));
  const fallback = languages.some((l) => l.code === DEFAULT_LANGUAGE) ? DEFAULT_LANGUAGE : languages[0]?.code ?? DEFAULT_LANGUAGE;
  const byDefault = typeof body?.default === 'string' && languages.some((l) => l.code === body.default) ? body.default : fallback;
  return { default: byDefault, languages };
}

/** The person's kept choice when the server speaks it, else the server's default. */
export function chooseLanguage(saved, list) {
  return list.languages.some((l) => l.code === saved) ? saved : list.default;
}

/** Fills `select` with the list, `chosen` selected. */
export function renderLanguages(select, list, chosen) {
  const options = list.languages.map(({ code, name }) => {
    const option = document.createElement('option');
    option.value = code;
    option.textContent = name === code ? code : `${name} (${code})`;
    option.selected = code === chosen;
    return option;
  });
  select.replaceChildren(...options);
  select.value = chosen;
}
