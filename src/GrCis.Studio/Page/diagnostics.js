// Compiler diagnostics in the editor: the line marked, the column underlined, a list below that jumps to each. Only
// those of the script the editor shows: another script's lines say nothing about this one.
import { $, state } from "./state.js";

export function showDiagnostics(list, scene) {
  const editor = state.editor.cm;
  if (!editor) return;
  if (scene !== state.editor.scene) list = [];
  for (const m of state.editor.marks) m.clear ? m.clear() : editor.removeLineClass(m, "background", "line-error");
  const marks = state.editor.marks = [];
  const ul = $("diagnostics");
  ul.innerHTML = "";
  for (const d of list) {
    const line = d.line - 1, ch = Math.max(0, d.column - 1);
    marks.push(editor.addLineClass(line, "background", "line-error"));
    marks.push(editor.markText({ line, ch }, { line, ch: ch + 1 }, { className: "cm-diagnostic", title: d.message }));
    const li = document.createElement("li");
    li.textContent = `${d.line}:${d.column} ${d.severity} ${d.id}: ${d.message}`;
    li.dataset.line = d.line;
    li.dataset.column = d.column;
    li.addEventListener("click", () => { editor.setCursor({ line, ch }); editor.focus(); });
    ul.appendChild(li);
  }
}
