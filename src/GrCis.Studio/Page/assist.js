// The editor's language services (Roslyn, through /api/editor): completion after "." or while typing a name (and on
// Ctrl+Space) with the selected entry's documentation, signature help inside a call's parentheses, the declaration and
// doc comment of a name under the pointer, and the compiler's errors marked as you type (checked without saving).
import { $, state } from "./state.js";

// The editor's text with an offset into it: what every request carries (CodeMirror's lines joined by "\n").
function request(cm, pos, extra) {
  return { text: cm.getValue(), position: cm.indexFromPos(pos), scene: state.editor.scene, ...extra };
}

async function post(path, body, signal) {
  const r = await fetch("api/editor/" + path, {
    method: "POST", signal,
    headers: { "Content-Type": "application/json", "X-GrCis-Tab": state.tab },
    body: JSON.stringify(body),
  });
  return r.status === 200 ? r.json() : null;
}

// One tooltip element per kind (signature, hover, documentation of the selected entry), placed at page coordinates.
function tip(id) {
  let el = $(id);
  if (!el) {
    el = document.createElement("div");
    el.id = id;
    el.className = "assist-tip";
    el.setAttribute("role", "tooltip");
    el.hidden = true;
    document.body.appendChild(el);
  }
  return el;
}

function place(el, left, top, above) {
  el.hidden = false;
  el.style.left = Math.max(4, Math.min(left, window.innerWidth - el.offsetWidth - 4)) + "px";
  el.style.top = (above ? top - el.offsetHeight - 4 : top + 4) + "px";
}

function fill(el, head, doc) {
  el.replaceChildren();
  const code = document.createElement("code");
  if (typeof head === "string") code.textContent = head; else code.append(...head);
  el.appendChild(code);
  if (doc) {
    const p = document.createElement("p");
    p.textContent = doc;
    el.appendChild(p);
  }
}

// Completion: CodeMirror's show-hint list filled from the server; it asks again as the word grows.
function hint(cm, callback) {
  const cursor = cm.getCursor();
  const body = request(cm, cursor);
  post("complete", body).then(result => {
    if (!result || result.items.length === 0) return callback(null);
    const list = result.items.map(item => ({
      text: item.label, item,
      render: (el, _, entry) => {
        const kind = document.createElement("span");
        kind.className = "assist-kind assist-kind-" + entry.item.kind;
        kind.textContent = entry.item.kind;
        el.append(entry.item.label, " ", kind);
      },
    }));
    const data = { list, from: cm.posFromIndex(result.from), to: cm.posFromIndex(result.to) };
    const doc = tip("assistDoc");
    CodeMirror.on(data, "select", async (entry, element) => {
      let described = entry.item;
      if (!described.detail) {
        described = await post("describe", { ...body, label: entry.item.label }) ?? entry.item;
        entry.item = described;
      }
      if (!described.detail) { doc.hidden = true; return; }
      fill(doc, described.detail, described.documentation);
      // Beside the list, once show-hint has placed it (the first entry is selected before the list is positioned).
      requestAnimationFrame(() => {
        if (!element.isConnected) return;
        const box = element.parentNode.getBoundingClientRect();
        doc.hidden = false;
        // Right of the list where it fits, else under it.
        if (box.right + 4 + doc.offsetWidth <= window.innerWidth) place(doc, box.right + 4, element.getBoundingClientRect().top - 4, false);
        else place(doc, box.left, box.bottom, false);
      });
    });
    CodeMirror.on(data, "close", () => { doc.hidden = true; });
    callback(data);
  }, () => callback(null));
}
hint.async = true;

function complete(cm) {
  cm.showHint({ hint, completeSingle: false, closeCharacters: /[\s()\[\]{};:>,=+\-*\/!&|?"']/ });
}

// Signature help: the overloads of the call around the caret, its current argument in bold; follows the caret.
let signatureAsk = null;
async function signature(cm) {
  const el = tip("assistSignature");
  signatureAsk?.abort();
  const ask = signatureAsk = new AbortController();
  let help;
  try { help = await post("signature", request(cm, cm.getCursor()), ask.signal); } catch { return; }
  if (ask !== signatureAsk) return;
  if (!help) { el.hidden = true; return; }
  const shown = help.signatures[help.active];
  const parts = [];
  const params = shown.parameters;
  const open = shown.label.indexOf("(");
  parts.push(shown.label.slice(0, open + 1));
  params.forEach((p, i) => {
    if (i > 0) parts.push(", ");
    if (i === help.activeParameter) { const b = document.createElement("b"); b.textContent = p.label; parts.push(b); } else parts.push(p.label);
  });
  parts.push(")");
  const count = help.signatures.length > 1 ? ` (${help.active + 1} of ${help.signatures.length})` : "";
  const active = params[help.activeParameter];
  fill(el, [...parts, count], [shown.documentation, active?.documentation ? `${active.label}: ${active.documentation}` : null].filter(Boolean).join("\n"));
  const at = cm.cursorCoords(null, "window");
  place(el, at.left, at.top, true);
}

// Hover: the name under the pointer, after it rests there a moment.
function hoverOn(cm) {
  const el = tip("assistHover");
  let timer = null, ask = null;
  const wrapper = cm.getWrapperElement();
  wrapper.addEventListener("mousemove", e => {
    clearTimeout(timer);
    el.hidden = true;
    timer = setTimeout(async () => {
      const pos = cm.coordsChar({ left: e.clientX, top: e.clientY }, "window");
      ask?.abort();
      const mine = ask = new AbortController();
      let info;
      try { info = await post("hover", request(cm, pos), mine.signal); } catch { return; }
      if (mine !== ask || !info) return;
      fill(el, info.text, info.documentation);
      place(el, e.clientX, e.clientY + 12, false);
    }, 450);
  });
  const hide = () => { clearTimeout(timer); ask?.abort(); el.hidden = true; };
  wrapper.addEventListener("mouseleave", hide);
  cm.on("change", hide);
}

// Errors as you type: the unsaved text compiled as the script (the newest text only), marked by CodeMirror's lint addon.
let checkAsk = null;
function annotations(text, update, _options, cm) {
  checkAsk?.abort();
  const ask = checkAsk = new AbortController();
  post("check", { text, position: 0, scene: state.editor.scene }, ask.signal).then(result => {
    if (ask !== checkAsk || !result || cm.getValue() !== text) return;
    update(result.diagnostics.map(d => {
      const from = CodeMirror.Pos(d.line - 1, Math.max(0, d.column - 1));
      // The token that starts there (a name, a string, a number), else one character.
      const token = cm.getTokenAt(CodeMirror.Pos(from.line, from.ch + 1), true);
      const to = CodeMirror.Pos(from.line, token.start === from.ch && token.end > from.ch ? token.end : from.ch + 1);
      return { from, to, message: `${d.id}: ${d.message}`, severity: d.severity === "error" ? "error" : "warning" };
    }));
  }, () => { });
}
annotations.async = true;

// Called once, when the editor is made.
export function assist(cm) {
  cm.setOption("gutters", ["CodeMirror-lint-markers"]);
  cm.setOption("lint", { getAnnotations: annotations, async: true, delay: 700 });
  const keys = cm.getOption("extraKeys") ?? {};
  cm.setOption("extraKeys", {
    ...keys,
    "Ctrl-Space": complete,
    "Esc": c => { tip("assistSignature").hidden = true; if (c.state.completionActive) c.state.completionActive.close(); },
  });
  cm.on("inputRead", (c, change) => {
    const typed = change.text.join("\n");
    if (/comment|string/.test(c.getTokenTypeAt(c.getCursor()) ?? "")) return;
    if (typed === ".") complete(c);
    else if (/^[A-Za-z_]$/.test(typed) && !c.state.completionActive && /[A-Za-z_]{2}$/.test(c.getLine(change.from.line).slice(0, change.from.ch + 1))) complete(c);
    if (typed === "(" || typed === ",") signature(c);
    else if (typed === ")") tip("assistSignature").hidden = true;
  });
  cm.on("cursorActivity", c => { if (!tip("assistSignature").hidden) signature(c); });
  cm.on("blur", () => { tip("assistSignature").hidden = true; });
  hoverOn(cm);
}
