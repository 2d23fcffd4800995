// The game's service worker: the page's files from the network when it answers (and kept), from
// the cache when it does not (offline play after the first visit); and the two headers the
// threads need (docs/web.md) added to every response, for hosts that do not send them.
'use strict';
const CACHE = 'coolaaber-1';
const FILES = ['coolaaber.html', 'coolaaber.js', 'coolaaber.wasm', 'coolaaber.worker.js',
               'coolaaber.data', 'coolaaber.webmanifest', 'icon.svg'];

self.addEventListener('install', (event) => {
  self.skipWaiting();
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(FILES)).catch(() => {}));
});

self.addEventListener('activate', (event) => event.waitUntil(self.clients.claim()));

function isolated(response) {
  if (response.status === 0) return response;  // opaque: not ours to change
  const headers = new Headers(response.headers);
  headers.set('Cross-Origin-Opener-Policy', 'same-origin');
  headers.set('Cross-Origin-Embedder-Policy', 'require-corp');
  return new Response(response.body, {status: response.status, statusText: response.statusText, headers});
}

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(
    fetch(request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          caches.open(CACHE).then((cache) => cache.put(request, copy));
        }
        return isolated(response);
      })
      .catch(() => caches.match(request, {ignoreSearch: true}).then((cached) => {
        if (!cached) throw new Error('offline, and ' + request.url + ' was never loaded');
        return isolated(cached);
      })));
});
