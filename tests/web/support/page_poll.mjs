// Waiting in a browser test until a page's state says something happened:
// `read(page)` gives the state (null while the page starts), polled every
// 200 ms until `predicate(state)` holds or `timeout` ms pass; the error
// names what did not happen and the last state seen.

export async function pageUntil(page, read, predicate, what, timeout = 30000) {
  const start = Date.now();
  for (;;) {
    const state = await read(page);
    if (state && predicate(state)) return state;
    if (Date.now() - start > timeout) throw new Error(`${what} did not happen within ${timeout / 1000} s: ${JSON.stringify(state)}`);
    await page.waitForTimeout(200);
  }
}
