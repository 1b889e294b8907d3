// Kinolab's service worker: the lab works offline once it has been opened,
// and a new release never mixes with the old one.
//
// Each release has its own cache, named by VERSION, filled with the whole
// lab at install (PRECACHE: the page, its script and its wasm, which holds
// the lessons). Pages are served from the cache of the release that
// controls them, so new wasm never meets an old page or the other way
// round. A new release installs beside the old one and waits; the page
// says a new version is ready and reloads into it when the learner agrees
// (the message "activate"). Only then are older caches deleted.
//
// VERSION and PRECACHE are written by web/stamp-sw.mjs after each build.
const VERSION = "unstamped";
const PRECACHE = ["./", "./index.html"];
const CACHE = `kinolab-${VERSION}`;

self.addEventListener("install", (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    await cache.addAll(PRECACHE);
    // The first release a browser sees starts at once: there is nothing
    // older to mix with.
    if (!self.registration.active) await self.skipWaiting();
  })());
});

self.addEventListener("message", (event) => {
  if (event.data === "activate") self.skipWaiting();
});

self.addEventListener("activate", (event) => {
  event.waitUntil((async () => {
    const keys = await caches.keys();
    await Promise.all(keys.filter((k) => k.startsWith("kinolab-") && k !== CACHE).map((k) => caches.delete(k)));
    await self.clients.claim();
  })());
});

self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) {
    return;
  }
  event.respondWith((async () => {
    const cache = await caches.open(CACHE);
    // Any address of the lab (`./`, `?probe`, `#/lesson`) is this release's
    // page; other pages (the embed page) are their own files.
    const path = new URL(request.url).pathname;
    const lab = request.mode === "navigate" && (path.endsWith("/") || path.endsWith("/index.html"));
    const cached = await cache.match(lab ? "./index.html" : request, { ignoreSearch: true });
    if (cached) return cached;
    const response = await fetch(request);
    // Files this release fetches later (the embed page and its package)
    // join its cache.
    if (response.ok) cache.put(request, response.clone());
    return response;
  })());
});
