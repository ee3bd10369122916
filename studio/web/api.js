// SPDX-License-Identifier: Apache-2.0
// Talking to the studio's server (docs/studio.md, "The API"): every request carries the token of
// the page's URL and this tab's client id (renders of one tab cancel each other, never another
// tab's); errors come back as {"error": MESSAGE} and are shown in the status line.

export const token = new URLSearchParams(location.search).get('token') || '';
// One id per tab: the server cancels a render in flight only for a newer render of the same tab.
export const clientId = Array.from(crypto.getRandomValues(new Uint8Array(8)),
                                   (b) => b.toString(16).padStart(2, '0')).join('');

export const $ = (id) => document.getElementById(id);

export function api(path, options = {}) {
  const headers = Object.assign({ 'X-Ifsfx-Token': token, 'X-Ifsfx-Client': clientId },
                                options.headers || {});
  if (typeof options.body === 'string') headers['Content-Type'] = 'application/json';
  return fetch(path, Object.assign({}, options, { headers }));
}

// The JSON answer of a GET, or an Error carrying the server's message.
export async function getJson(path) {
  const res = await api(path);
  const body = await res.json();
  if (!res.ok) throw new Error(body.error || `HTTP ${res.status}`);
  return body;
}

// POSTs `body` as JSON; the answer's JSON, or an Error carrying the server's message.
export async function postJson(path, body) {
  const res = await api(path, { method: 'POST', body: JSON.stringify(body) });
  const answer = await res.json();
  if (!res.ok) throw new Error(answer.error || `HTTP ${res.status}`);
  return answer;
}

export function status(text, error = false) {
  $('status').textContent = text;
  $('status').className = error ? 'error' : '';
}
