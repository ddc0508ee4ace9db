// Requests to the studio: every one names the page's tab; an error answer, problem details (RFC 7807), becomes an
// Error with its detail, the sentence the page shows.
import { state } from "./state.js";

export async function api(path, options) {
  const r = await fetch("api/" + path, { ...options, headers: { ...options?.headers, "X-GrCis-Tab": state.tab } });
  if (!r.ok && r.status !== 404) throw new Error(await problemText(r));
  return r;
}

// The sentence of an error answer: the problem's detail, else its title, else the text or the status.
export async function problemText(r) {
  let text = await r.text();
  try {
    const problem = JSON.parse(text);
    text = problem.detail ?? problem.title ?? text;
  } catch { }
  return text || r.statusText;
}
