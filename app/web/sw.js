// springlab's service worker: a page opened once works with the network off (docs/web.md,
// Offline). The build (app/web/site.cmake) writes in this build's cache name and its files, each
// with its SHA-256, so this file changes with every build and the browser installs the new one.
//
// - install: fetch every file of the build, check each against its SHA-256 (a file from another
//   build, e.g. while a host is half-way through publishing, fails the install: the old version
//   stays, whole), and only then store them in this build's cache;
// - activate: delete every other springlab cache, take over the open pages;
// - fetch: the build's files are versioned (index.html asks for springlab.js?v=..., the same for
//   the .wasm, .data, manifest and icons), served from this build's cache first; the page itself is
//   fetched network first (a new build's index.html asks for new versions, which miss this cache
//   and come from the network: never a mix), and from the cache when the network fails or is slow,
//   whatever its query (?...) and fragment (#scene=...).
"use strict";
const CACHE = "springlab-@SPRINGLAB_CACHE_VERSION@";
const FILES = @SPRINGLAB_SITE_FILES@;
const PAGE = new URL("index.html", self.registration.scope).href;
const SCOPE = new URL(self.registration.scope).pathname;
const VERSIONED = new Set(FILES.map((f) => new URL(f.url, self.registration.scope).href));
const NETWORK_WAIT_MS = 4000;  // then the cached page (a phone with a poor signal)

const hex = (buffer) => Array.from(new Uint8Array(buffer), (b) => b.toString(16).padStart(2, "0")).join("");

self.addEventListener("install", (event) => {
  event.waitUntil((async () => {
    const files = await Promise.all(FILES.map(async ({ url, sha256 }) => {
      const response = await fetch(url, { cache: "no-cache" });
      if (!response.ok) throw new Error(`springlab: ${url}: HTTP ${response.status}`);
      const body = await response.arrayBuffer();
      if (hex(await crypto.subtle.digest("SHA-256", body)) !== sha256)
        throw new Error(`springlab: ${url} is not this build's (is a new one being published?)`);
      // (Only the type: the body is decoded already, so a Content-Encoding or -Length would lie.)
      const type = response.headers.get("Content-Type") || "application/octet-stream";
      return [url, new Response(body, { status: 200, headers: { "Content-Type": type } })];
    }));
    const cache = await caches.open(CACHE);
    try {
      for (const [url, response] of files) await cache.put(url, response);
    } catch (e) {
      await caches.delete(CACHE);
      throw e;
    }
    await self.skipWaiting();
  })());
});

self.addEventListener("activate", (event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys())
      if (name.startsWith("springlab-") && name !== CACHE) await caches.delete(name);
    await self.clients.claim();
  })());
});

// The page: the network's, unless it fails, answers with an error or takes too long.
async function page(request) {
  const network = fetch(request.url, { cache: "no-cache", credentials: "same-origin" });
  let timer;
  const slow = new Promise((resolve) => { timer = setTimeout(() => resolve(null), NETWORK_WAIT_MS); });
  const first = await Promise.race([network.catch(() => null), slow]);
  clearTimeout(timer);
  if (first && first.ok) return first;
  const cached = await (await caches.open(CACHE)).match(PAGE);
  return cached || first || network;  // no page cached: the network's answer, or its error
}

self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET") return;
  const url = new URL(request.url);
  if (url.origin !== self.location.origin) return;
  if (request.mode === "navigate" && (url.pathname === SCOPE || url.pathname === SCOPE + "index.html")) {
    event.respondWith(page(request));
  } else if (VERSIONED.has(url.href)) {
    event.respondWith(caches.open(CACHE).then((cache) => cache.match(request, { ignoreVary: true })).then((hit) => hit || fetch(request)));
  }
  // Anything else (another build's files, the test pages under _build/) goes to the network as usual.
});
