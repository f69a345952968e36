// The HTTP API (/api/v1) as the pages use it: JSON with ETag revalidation for polling,
// problem+json errors kept whole, and the bearer token (sessionStorage only) on writes.
const TOKEN_KEY = 'slipfront.token';
const etags = new Map(); // url -> {etag, body}

export function token() {
  return sessionStorage.getItem(TOKEN_KEY) || '';
}
export function setToken(t) {
  if (t) sessionStorage.setItem(TOKEN_KEY, t);
  else sessionStorage.removeItem(TOKEN_KEY);
}

export class ApiError extends Error {
  constructor(status, problem) {
    super(problem?.detail || problem?.title || `HTTP ${status}`);
    this.status = status;
    this.problem = problem || {};
    this.errors = Array.isArray(problem?.errors) ? problem.errors : [];
  }
}

async function parse(res) {
  const type = res.headers.get('Content-Type') || '';
  if (type.includes('json')) return res.json();
  return res.text();
}

// GET with If-None-Match: the cached body when the server answers 304.
// Returns {body, changed}.
export async function getJSON(url, { revalidate = true } = {}) {
  const headers = { Accept: 'application/json' };
  const cached = etags.get(url);
  if (revalidate && cached) headers['If-None-Match'] = cached.etag;
  const res = await fetch(url, { headers, cache: 'no-store' });
  if (res.status === 304 && cached) return { body: cached.body, changed: false };
  const body = await parse(res);
  if (!res.ok) throw new ApiError(res.status, typeof body === 'object' ? body : { detail: body });
  const etag = res.headers.get('ETag');
  if (etag) {
    etags.set(url, { etag, body });
    if (etags.size > 300) etags.delete(etags.keys().next().value);
  }
  return { body, changed: true };
}

export async function get(url) {
  return (await getJSON(url)).body;
}

export async function post(url, payload) {
  return send('POST', url, payload);
}

// A write (POST, PATCH, DELETE) with the token; the answer's JSON, or an ApiError.
export async function send(method, url, payload) {
  const headers = { Accept: 'application/json' };
  if (payload !== undefined) headers['Content-Type'] = 'application/json';
  const t = token();
  if (t) headers.Authorization = `Bearer ${t}`;
  const res = await fetch(url, {
    method, headers, cache: 'no-store',
    body: payload === undefined ? undefined : JSON.stringify(payload),
  });
  const body = await parse(res);
  if (!res.ok) throw new ApiError(res.status, typeof body === 'object' ? body : { detail: body });
  return body;
}

// A file the server writes for a user (an archive: it needs the token on a shared server), as
// a Blob; an ApiError when refused.
export async function download(url) {
  const headers = {};
  const t = token();
  if (t) headers.Authorization = `Bearer ${t}`;
  const res = await fetch(url, { headers, cache: 'no-store' });
  if (!res.ok) {
    const body = await parse(res);
    throw new ApiError(res.status, typeof body === 'object' ? body : { detail: body });
  }
  return res.blob();
}

export function qs(params) {
  const u = new URLSearchParams();
  for (const [k, v] of Object.entries(params)) if (v !== undefined && v !== null && v !== '') u.set(k, v);
  const s = u.toString();
  return s ? `?${s}` : '';
}
