// The message line: another tab's takeover, the render's notes and error, and the page's own error and note.
import { $, state } from "./state.js";

const tookOver = "Another tab or window of this studio started what is on show (one render at a time; Render here to take it back).";

export function showMessages() {
  const s = state.studio;
  const other = s.tab && s.tab !== state.tab ? tookOver : "";
  $("messages").textContent = [other, ...s.notes, s.error, state.pageError, state.pageNote].filter(Boolean).join("\n");
}

// The page's own error (a refused request), shown until the next action; "" clears it.
export function showError(message) {
  state.pageError = message;
  state.pageNote = "";
  showMessages();
}

// A passing word (what the page just did): replaced by the next change of the studio's state.
export function say(text) {
  $("messages").textContent = text;
}
