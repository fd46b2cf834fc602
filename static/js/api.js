/**
 * api.js — requests to our own API: the one retry loop of the pages.
 *
 *   fetchJSON(url, {body, signal, tries, onWait})
 *       GET (no body) or POST the body as JSON; resolves to the JSON answer.  A 429 or 503 (a
 *       job of this session still running, the server busy) is retried: after its Retry-After,
 *       else after a backoff that doubles (0.5 s, 1 s, 2 s … at most 8 s), at most `tries` times
 *       in all (6 unless told).  Any other refusal rejects with RequestError: its message is the
 *       API's "detail", with .status and .answer (the refusal's JSON: loc, part, start, end …).
 *   fetchRetrying(url, init, {tries, patience, onWait})
 *       the same retries for any request (a download, a call that reads the status itself): the
 *       Response; a Retry-After longer than `patience` seconds is not waited for.  `onWait(seconds)`
 *       is called before each wait, so a page can say that it is waiting and for how long.
 *   inTurn(job)  the session's jobs one at a time: the server runs one job per session and answers a
 *       second one 429, so the page's derivation, practice steps, checks, modes and sections wait their
 *       turn here (one queue for every script of the page) rather than be told to wait there.
 *   sleep(ms, signal)  a promise resolved after ms (rejected when the signal aborts).
 */
export const sleep = (ms, signal) => new Promise((resolve, reject) => {
  const timer = setTimeout(resolve, ms);
  signal?.addEventListener("abort", () => {
    clearTimeout(timer);
    reject(signal.reason ?? new DOMException("aborted", "AbortError"));
  }, { once: true });
});

export class RequestError extends Error {
  constructor(message, status, answer) {
    super(message);
    this.status = status;
    this.answer = answer;
  }
}

const BUSY = new Set([429, 503]);

/** How long to wait before try number `attempt` + 1: the server's Retry-After, else a doubling backoff. */
function delay(response, attempt) {
  const asked = Number(response.headers.get("Retry-After"));
  return asked > 0 ? 1000 * asked : Math.min(8000, 500 * 2 ** attempt);
}

export async function fetchRetrying(url, init = {}, { tries = 6, patience = Infinity, onWait = null } = {}) {
  for (let attempt = 1; ; attempt++) {
    const response = await fetch(url, init);
    if (!BUSY.has(response.status) || attempt >= tries) return response;
    const wait = delay(response, attempt - 1);
    if (wait > 1000 * patience) return response;
    onWait?.(Math.ceil(wait / 1000));
    await sleep(wait, init.signal);
  }
}

let turn = Promise.resolve();
export function inTurn(job) {
  const next = turn.then(job, job);
  turn = next.catch(() => null);
  return next;
}

export async function fetchJSON(url, { body, signal, tries, onWait } = {}) {
  const init = body === undefined
    ? { headers: { Accept: "application/json" }, signal }
    : { method: "POST", headers: { "Content-Type": "application/json", Accept: "application/json" }, body: JSON.stringify(body), signal };
  const response = await fetchRetrying(url, init, { tries, onWait });
  let answer = null;
  try { answer = await response.json(); } catch { answer = null; }
  if (response.ok) return answer;
  const detail = answer && answer.detail ? answer.detail : `the server answered ${response.status}`;
  throw new RequestError(typeof detail === "string" ? detail : JSON.stringify(detail), response.status, answer);
}
