// The face lab's "Contact sheet" button and the dialog that shows the sheet
// (contact_sheet.js draws it): the image, a "Download PNG" link to it (a
// blob URL, named by the avatar and the time) and Close; Escape closes it
// too (a modal <dialog>'s own cancel). The face parameters are frozen when
// the button is pressed; the drawing waits for the next task, so that the
// button can say it is at work first.
import { arrangementFor, renderContactSheet, sheetFileName } from './contact_sheet.js';

/** What the dialog leaves of the screen for the image (lab.css: .sheet-dialog and its img), CSS pixels. */
const spaceForSheet = () => [0.96 * window.innerWidth - 32, 0.94 * window.innerHeight - 150];

/**
 * Wires `button` to show the sheet of the lab view `view` for the avatar
 * named `name`. Returns { dialog, last }, last being the newest sheet
 * ({ layout, arrangement, params, url, fileName }), for whoever inspects the page.
 */
export function wireContactSheet({ button, view, name }) {
  const parts = buildDialog();
  const state = { dialog: parts.dialog, last: null };
  let url = null;
  const letGo = () => {
    if (url) URL.revokeObjectURL(url);
    url = null;
    parts.image.removeAttribute('src');
    parts.download.removeAttribute('href');
  };
  parts.dialog.addEventListener('close', letGo);
  parts.close.addEventListener('click', () => parts.dialog.close());

  button.addEventListener('click', () => {
    const params = view.drawnParams && structuredClone(view.drawnParams);  // frozen: later frames do not change this sheet
    const taken = new Date();
    button.disabled = true;
    const label = button.textContent;
    button.textContent = 'Drawing…';
    setTimeout(async () => {
      try {
        letGo();
        const sheet = renderContactSheet(view, params, arrangementFor(...spaceForSheet()));
        if (!sheet) return show(parts, 'Your face has not been drawn yet: wait until it shows, then ask again.');
        const blob = await new Promise((resolve) => { sheet.canvas.toBlob(resolve, 'image/png'); });
        if (!blob) return show(parts, 'This browser could not make a PNG of the sheet.');
        url = URL.createObjectURL(blob);
        const fileName = sheetFileName(name, taken);
        parts.image.src = url;
        parts.image.width = sheet.layout.width;
        parts.image.height = sheet.layout.height;
        parts.download.href = url;
        parts.download.download = fileName;
        state.last = { layout: sheet.layout, arrangement: sheet.arrangement, params: sheet.params, url, fileName };
        return show(parts, `As your preview showed it at ${taken.toLocaleTimeString()}.`);
      } catch (error) {
        return show(parts, `The sheet could not be drawn: ${error.message}`);
      } finally {
        button.disabled = false;
        button.textContent = label;
      }
    }, 0);
  });
  return state;
}

function show(parts, caption) {
  parts.caption.textContent = caption;
  parts.image.hidden = !parts.image.getAttribute('src');
  parts.download.hidden = !parts.download.getAttribute('href');
  if (!parts.dialog.open) parts.dialog.showModal();
}

function buildDialog() {
  const element = (tag, props = {}, ...children) => {
    const e = Object.assign(document.createElement(tag), props);
    e.append(...children);
    return e;
  };
  const image = element('img', { alt: 'contact sheet: your face from the front, turned both ways, from above and below' });
  const caption = element('p', { className: 'hint', id: 'sheet-caption' });
  const download = element('a', { className: 'button primary', id: 'sheet-download' }, 'Download PNG');
  const close = element('button', { className: 'button', type: 'button', id: 'sheet-close' }, 'Close');
  const dialog = element('dialog', { className: 'sheet-dialog', id: 'sheet-dialog' },
    element('h2', { id: 'sheet-title' }, 'Contact sheet'), caption, image, element('div', { className: 'row' }, download, close));
  dialog.setAttribute('aria-labelledby', 'sheet-title');
  document.body.append(dialog);
  return { dialog, image, caption, download, close };
}
