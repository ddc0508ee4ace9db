// The script editor (CodeMirror): open the chosen scene's script, save it (Ctrl+S: once), and follow changes made on
// disk by another editor: reloaded when nothing is edited here, else the user is asked.
import { $, state } from "./state.js";
import { api, problemText } from "./api.js";
import { showError, say } from "./messages.js";
import { showStatus } from "./status.js";
import { assist } from "./assist.js";
import { applySplit, initSplit } from "./split.js";
import { showDiagnostics } from "./diagnostics.js";

const ed = state.editor;

async function openEditor() {
  const name = $("scene").value;
  const r = await api("source?scene=" + encodeURIComponent(name));
  if (!r.ok) { showError(`${name} is not a script file`); return; }
  const text = await r.text();
  $("editorPane").hidden = false;
  applySplit();
  $("editorName").textContent = state.scenes.find(x => x.name === name)?.file ?? name;
  if (!ed.cm) {
    // The text itself is the editable element (contenteditable, not CodeMirror's hidden textarea): screen readers read
    // it, and the region that scrolls the code is the one the keyboard is in.
    ed.cm = CodeMirror($("editor"), { value: text, mode: "text/x-csharp", lineNumbers: true, indentUnit: 2, tabSize: 2, inputStyle: "contenteditable" });
    ed.cm.setOption("extraKeys", { "Ctrl-S": save, "Cmd-S": save });
    assist(ed.cm);
  }
  awaitLanguageServices();
  ed.scene = name;
  loadSource(text, r.headers.get("ETag"));
  // The errors of a render that failed before the editor was opened (or while it showed another text) are marked now.
  showDiagnostics(state.studio.diagnostics, state.studio.diagnosticsScene);
  // The file on disk is asked for its version once a second while the editor is open (a 304 while unchanged).
  clearInterval(ed.timer);
  ed.timer = setInterval(checkSource, 1000);
}

// Until the studio's language services have loaded (a few seconds after it starts), the editor bar says so: the first
// completion would otherwise seem not to come.
function awaitLanguageServices() {
  if (ed.ready) return;
  const shown = setTimeout(() => { $("assistLoading").hidden = false; }, 300);
  ed.ready = api("editor/ready").catch(() => null).finally(() => {
    clearTimeout(shown);
    $("assistLoading").hidden = true;
  });
}

function closeEditor() {
  $("editorPane").hidden = true;
  clearInterval(ed.timer);
  ed.timer = null;
}

// The editor shows the file's text as it is on disk, with no unsaved edits.
function loadSource(text, tag) {
  ed.epoch++;
  const cursor = ed.cm.getCursor();
  if (ed.cm.getValue() !== text) ed.cm.setValue(text);
  ed.cm.setCursor(cursor);
  ed.cm.markClean();
  ed.tag = tag;
  ed.diskTag = ed.diskText = null;
  $("sourceChanged").hidden = true;
}

// Another editor changed the open script: the text is reloaded, or, over unsaved edits, the user is asked.
export async function checkSource() {
  if (!ed.cm || !ed.scene || $("editorPane").hidden || ed.checking) return;
  ed.checking = true;
  const epoch = ed.epoch;
  try {
    const r = await fetch("api/source?scene=" + encodeURIComponent(ed.scene), {
      cache: "no-store", headers: ed.tag ? { "If-None-Match": ed.tag } : {},
    });
    const tag = r.headers.get("ETag");
    if (r.status !== 200 || epoch !== ed.epoch || tag === ed.tag || tag === ed.diskTag) return;
    const text = await r.text();
    if (epoch !== ed.epoch) return;   // saved or reloaded meanwhile
    if (ed.cm.isClean() || ed.cm.getValue() === text) {
      loadSource(text, tag);
      state.pageNote = `${$("editorName").textContent} changed on disk: reloaded`;
    } else {
      ed.diskTag = tag;
      ed.diskText = text;
      $("sourceChanged").hidden = false;
    }
  } catch { } finally {
    ed.checking = false;
  }
}

export async function save() {
  if (!ed.cm || !ed.scene) return;
  ed.epoch++;
  const text = ed.cm.getValue(), headers = { "Content-Type": "text/plain; charset=utf-8", "X-GrCis-Tab": state.tab };
  // Only over the text it was loaded from (or the disk's, once the user chose to keep theirs): never over a newer file unseen.
  if (ed.tag) headers["If-Match"] = ed.tag;
  try {
    const events = state.events;
    const r = await fetch("api/source?scene=" + encodeURIComponent(ed.scene), { method: "PUT", headers, body: text });
    if (r.status === 412) {
      await checkSource();   // asks, showing the bar (or reloads, when nothing was edited)
      return;
    }
    if (!r.ok) throw new Error(await problemText(r));
    ed.epoch++;
    ed.tag = r.headers.get("ETag");
    if (ed.cm.getValue() === text) ed.cm.markClean();
    // 204: the rendered script, which the studio re-renders; 202: another script, which it compiles (its check's number
    // comes back, and the event that it ended carries it).
    if (r.status === 202) state.compilingSave = { name: $("editorName").textContent, check: (await r.json()).check };
    state.pageError = state.pageNote = "";
    showStatus();
    // Until the studio's next event says more (unless its events on this save came before the answer).
    if (state.events === events) say("saved; compiling…");
  } catch (e) {
    showError(e.message);
  }
}

export function initEditor() {
  initSplit();
  $("edit").addEventListener("click", openEditor);
  $("save").addEventListener("click", save);
  $("closeEditor").addEventListener("click", closeEditor);
  $("reloadSource").addEventListener("click", () => { if (ed.diskText !== null) loadSource(ed.diskText, ed.diskTag); });
  $("keepMine").addEventListener("click", () => {
    // The next save replaces the file on disk with the editor's text.
    ed.tag = ed.diskTag ?? ed.tag;
    ed.diskTag = ed.diskText = null;
    $("sourceChanged").hidden = true;
  });
  document.addEventListener("keydown", e => {
    // In the editor CodeMirror's own Ctrl+S has saved already (and prevented the default): one save per key press.
    if ((e.ctrlKey || e.metaKey) && e.key === "s" && !e.defaultPrevented) { e.preventDefault(); save(); }
  });
}
