import { openWeb, sourceFile } from '../support/harness.mjs';
const web = await openWeb([]);
try {
  for (const [w, h, name] of [[1280, 800, 'desktop'], [390, 844, 'phone']]) {
    const page = await web.page({ width: w, height: h });
    await page.goto(web.server.url);
    await page.waitForTimeout(1500);
    await page.screenshot({ path: `/tmp/s40/lobby-${name}-0.png`, fullPage: true });
    await page.fill('#name', 'Tester');
    await page.setInputFiles('#photo-file', sourceFile('tests/data/astronaut.png'));
    await page.locator('#avatar-preview').waitFor({ state: 'visible', timeout: 90000 });
    await page.waitForTimeout(1500);
    await page.screenshot({ path: `/tmp/s40/lobby-${name}-1.png`, fullPage: true });
  }
} finally { await web.close(); }
