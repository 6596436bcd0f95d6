// What the server said of a face script the lab checked or played
// (server/simulation/script_check.hpp: "line L, column C: what was wrong";
// a script played: "script L:C: ..." (avatar/behavior's room_script.hpp)),
// as the editor shows it: the place to put the caret, and the words.
const PLACE = /(?:line (\d+), column (\d+)|script (\d+):(\d+)): /;

/** { line, column, message } of an error; line and column null when it names no place; null when accepted. */
export function readScriptResult(error) {
  if (!error) return null;
  const place = PLACE.exec(error);
  if (!place) return { line: null, column: null, message: error };
  const [line, column] = place[1] ? [place[1], place[2]] : [place[3], place[4]];
  return { line: Number(line), column: Number(column), message: error.slice(place.index + place[0].length) };
}

/** The offset in `text` of 1-based `line` and `column` (columns count bytes; fine for ASCII scripts). */
export function offsetOf(text, line, column) {
  let offset = 0;
  for (let l = 1; l < line; ++l) {
    const next = text.indexOf('\n', offset);
    if (next < 0) return text.length;
    offset = next + 1;
  }
  return Math.min(text.length, offset + Math.max(0, column - 1));
}
