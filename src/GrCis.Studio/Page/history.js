// The kept renders: back and forward, and A/B, a kept render (B) over the one on show (A), cut at a slider.
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError } from "./messages.js";
import { place } from "./view.js";

export async function loadHistory(list) {
  const h = list ?? await (await api("history")).json();
  $("back").disabled = !h.canGoBack;
  $("forward").disabled = !h.canGoForward;
  $("historyLabel").textContent = $("historyLabel").title =
    h.position >= 0 ? `${h.position + 1}/${h.items.length}: ${h.items[h.position].label}` : "";
  // The B choices: every kept render; a choice whose render is no longer the same one is dropped.
  const select = $("abWith"), chosen = select.value, chosenLabel = select.selectedOptions[0]?.textContent;
  select.length = 1;
  h.items.forEach((item, i) => select.add(new Option(`${i + 1}: ${item.label}`, String(i))));
  select.value = chosen !== "" && select.options[Number(chosen) + 1]?.textContent === chosenLabel ? chosen : "";
  if (select.value !== chosen) await compareWith();
}

// The image on show follows (the studio announces it as a new image).
async function moveHistory(direction) {
  try {
    await loadHistory(await (await api("history/" + direction, { method: "POST" })).json());
    state.viewsFor = -1;
  } catch (e) {
    showError(e.message);
  }
}

// A/B: a kept render (B) drawn over the image on show (A), placed as it is and cut at the split: A left of it, B right.
async function compareWith() {
  const i = $("abWith").value, b = $("canvasB");
  $("abSplit").hidden = b.hidden = i === "";
  if (i === "") return;
  try {
    const bitmap = await createImageBitmap(await (await api(`history/${i}.png`)).blob());
    b.width = bitmap.width;
    b.height = bitmap.height;
    b.getContext("2d").drawImage(bitmap, 0, 0);
    b.dataset.item = i;
    split();
    place();
  } catch (e) {
    showError(e.message);
  }
}

function split() { $("canvasB").style.clipPath = `inset(0 0 0 ${$("abSplit").value}%)`; }

export function initHistory() {
  $("back").addEventListener("click", () => moveHistory("back"));
  $("forward").addEventListener("click", () => moveHistory("forward"));
  $("abWith").addEventListener("change", compareWith);
  $("abSplit").addEventListener("input", split);
}
