// The message box above the image: another tab's takeover, the render's notes and error, and the page's own error and
// note. A message stays until the user dismisses it or the next action replaces it; errors are marked as such.
import { $, state } from "./state.js";

const tookOver = "Another tab or window of this studio started what is on show (one render at a time; Render here to take it back).";

// The text the user dismissed: not shown again while the messages are just that.
let dismissed = "";

function show(text, error) {
  $("messages").textContent = text;
  $("messageBox").hidden = text === "";
  $("messageBox").classList.toggle("error", error);
}

export function showMessages() {
  const s = state.studio;
  // A fresh tab took nothing back from anyone: the notice is for a tab whose own render was replaced.
  const other = s.tab && s.tab !== state.tab && state.ownedRender ? tookOver : "";
  // The error and notes of a render of a scene no longer chosen are not this scene's.
  const own = state.staleRender !== s.renderId;
  // Each once: a script that fails as it runs fails the same way when its values are read (the page's error) and when rendered.
  const text = [...new Set([other, ...(own ? s.notes : []), own ? s.error : "", state.pageError, state.pageNote].filter(Boolean))].join("\n");
  if (text !== dismissed) dismissed = "";
  show(text === dismissed ? "" : text, Boolean(s.error || state.pageError));
}

// The page's own error (a refused request), shown until the next action; "" clears it.
export function showError(message) {
  state.pageError = message;
  state.pageNote = "";
  showMessages();
}

// A passing word (what the page just did): replaced by the next change of the studio's state.
export function say(text) {
  show(text, false);
}

export function initMessages() {
  $("dismiss").addEventListener("click", () => {
    dismissed = $("messages").textContent;
    show("", false);
  });
}
