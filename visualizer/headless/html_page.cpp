#include "headless/html_page.hpp"
#include <md4c-html.h>
#include <array>
#include <utility>

namespace sw::vis {
namespace {

// Replaces href="..." and src="..." values whose scheme is not http, https or mailto with "#".
// md4c writes these attributes itself (raw HTML is off), always double-quoted; a target without
// a scheme (a relative path, "#anchor") is kept.
std::string neutralize_urls(const std::string& html) {
  std::string out;
  std::size_t i = 0;
  for (;;) {
    const std::size_t href = html.find(" href=\"", i), src = html.find(" src=\"", i);
    const std::size_t at = std::min(href, src);
    if (at == std::string::npos) break;
    const std::size_t begin = at + (at == href ? 7 : 6), end = html.find('"', begin);
    if (end == std::string::npos) break;
    const std::string_view url(html.data() + begin, end - begin);
    const std::size_t colon = url.find(':'), stop = url.find_first_of("/?#");
    bool safe = colon == std::string_view::npos || (stop != std::string_view::npos && stop < colon);
    if (!safe) {
      std::string scheme(url.substr(0, colon));
      for (char& c : scheme) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
      safe = scheme == "http" || scheme == "https" || scheme == "mailto";
    }
    out.append(html, i, begin - i);
    out += safe ? std::string(url) : std::string("#");
    i = end;
  }
  out.append(html, i, std::string::npos);
  return out;
}

// The page; @TITLE@, @INTRO@, @DATA@, @W@ and @H@ are filled in once each by lesson_page.
constexpr std::string_view kPage = R"HTML(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src 'self' file:; style-src 'unsafe-inline'; script-src 'unsafe-inline'">
<title>@TITLE@</title>
<style>
body { margin: 0; background: #1a1a1f; color: #dde0e6; font: 15px/1.5 system-ui, sans-serif; }
header, #intro-box, main, footer { max-width: 1800px; margin: 0 auto; padding: 0 16px; }
h1 { font-size: 1.5em; margin: 16px 0 4px; }
h2 { font-size: 1em; margin: 12px 0 6px; color: #aab; }
.meta, footer { color: #889; font-size: 0.9em; }
#intro-box summary { cursor: pointer; color: #aab; }
main { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; margin-top: 12px; }
#stage { flex: 3 1 640px; min-width: 0; }
#frame { display: block; max-width: 100%; height: auto; border: 1px solid #333; background: #000; }
#controls { display: flex; flex-wrap: wrap; align-items: center; gap: 8px; margin: 8px 0; }
#controls button { background: #2c2f3a; color: #eee; border: 1px solid #445; border-radius: 4px; padding: 4px 10px; cursor: pointer; }
#controls button:disabled { opacity: 0.4; cursor: default; }
#slider { flex: 1 1 200px; }
#kind { background: #35304a; border-radius: 4px; padding: 1px 8px; font-family: monospace; }
aside { flex: 2 1 360px; min-width: 0; }
#listing { position: relative; max-height: 45vh; overflow: auto; margin: 0; padding: 6px 0; list-style: none;
  background: #14141a; border: 1px solid #333; font: 13px/1.45 "DejaVu Sans Mono", monospace; }
#listing li { display: flex; gap: 10px; padding: 0 8px; white-space: pre-wrap; }
#listing .num { color: #667; min-width: 2ch; text-align: right; flex: none; }
#listing .comment { color: #7a8090; }
#listing li.current { background: #3b4a7a; color: #fff; }
#listing li.current .comment { color: #d8e0ff; }
#narration { background: #22222b; border-left: 3px solid #e8c070; padding: 2px 12px; min-height: 2em; color: #ffeec0; }
#narration:empty::before { content: "No narration at this step."; color: #778; font-style: italic; }
code { background: #2a2a33; padding: 0 3px; border-radius: 3px; }
</style>
</head>
<body>
<header>
<h1 id="title">@TITLE@</h1>
<p class="meta" id="meta"></p>
</header>
<details id="intro-box" open><summary>Introduction</summary><div id="intro">@INTRO@</div></details>
<main>
<section id="stage">
<img id="frame" alt="" width="@W@" height="@H@">
<div id="controls">
<button id="first" title="First step (Home)">|&#x25C0;</button>
<button id="prev" title="Previous step (Left)">&#x25C0;</button>
<button id="play" title="Play or pause (Space)">Play</button>
<button id="next" title="Next step (Right)">&#x25B6;</button>
<button id="last" title="Last step (End)">&#x25B6;|</button>
<input id="slider" type="range" min="0" max="0" value="0" aria-label="Step">
<span>Step <b id="step">0</b> of <span id="last-step">0</span></span>
<span id="kind"></span>
<select id="speed" title="Steps per second when playing"><option value="1">1/s</option><option value="2" selected>2/s</option><option value="5">5/s</option><option value="10">10/s</option></select>
</div>
<noscript><p>This page needs JavaScript to step through the frames.</p></noscript>
</section>
<aside>
<h2 id="listing-title">Listing</h2>
<ol id="listing"></ol>
<h2>At this step</h2>
<div id="narration"></div>
</aside>
</main>
<footer><p>Keys: Left and Right step, Home and End, Space plays. Written by <code>stepwise lesson export</code>.</p></footer>
<script type="application/json" id="page-data">@DATA@</script>
<script>
(function () {
  'use strict';
  const D = JSON.parse(document.getElementById('page-data').textContent);
  const $ = (id) => document.getElementById(id);
  const frame = $('frame'), slider = $('slider'), listing = $('listing'), narration = $('narration');
  const n = D.steps.length;
  let at = 0, timer = null, shownListing = -1;
  slider.max = String(n - 1);
  $('last-step').textContent = String(D.steps[n - 1].step);
  $('meta').textContent = D.algorithm + ', ' + D.numeric + ': steps ' + D.steps[0].step + ' to ' + D.steps[n - 1].step;

  function buildListing(k) {
    const L = D.listings[k];
    $('listing-title').textContent = L.title;
    listing.replaceChildren();
    L.lines.forEach(function (line, i) {
      const row = document.createElement('li'), num = document.createElement('span'), code = document.createElement('span');
      const c = line.text.indexOf('--');
      num.className = 'num';
      num.textContent = String(i + 1);
      code.textContent = c < 0 ? line.text : line.text.slice(0, c).trimEnd() + '  ';
      if (c >= 0) {  // the comment follows the code and wraps with it
        const comment = document.createElement('span');
        comment.className = 'comment';
        comment.textContent = line.text.slice(c);
        code.append(comment);
      }
      row.append(num, code);
      row.dataset.line = String(i + 1);
      row.title = line.name;
      listing.append(row);
    });
    shownListing = k;
  }

  function show(i) {
    at = Math.max(0, Math.min(n - 1, i));
    const s = D.steps[at];
    frame.src = s.frame;
    frame.alt = 'Step ' + s.step;
    $('step').textContent = String(s.step);
    $('kind').textContent = s.kind;
    slider.value = String(at);
    if (s.listing !== shownListing) buildListing(s.listing);
    let current = null;
    for (const row of listing.children) {
      const on = Number(row.dataset.line) === s.line;
      row.classList.toggle('current', on);
      if (on) current = row;
    }
    if (current) listing.scrollTop = current.offsetTop - listing.clientHeight / 2;
    narration.innerHTML = D.narrations[s.narration];
    $('first').disabled = $('prev').disabled = at === 0;
    $('next').disabled = $('last').disabled = at === n - 1;
    if (at + 1 < n) new Image().src = D.steps[at + 1].frame;  // the next frame shows at once
  }

  function stop() {
    if (timer !== null) clearInterval(timer);
    timer = null;
    $('play').textContent = 'Play';
  }
  function go(i) { stop(); show(i); }
  function play() {
    if (timer !== null) return stop();
    if (at === n - 1) show(0);
    timer = setInterval(function () { if (at >= n - 1) stop(); else show(at + 1); }, 1000 / Number($('speed').value));
    $('play').textContent = 'Pause';
  }

  $('first').onclick = function () { go(0); };
  $('prev').onclick = function () { go(at - 1); };
  $('next').onclick = function () { go(at + 1); };
  $('last').onclick = function () { go(n - 1); };
  $('play').onclick = play;
  $('speed').onchange = function () { if (timer !== null) { stop(); play(); } };
  slider.oninput = function () { go(Number(slider.value)); };
  document.addEventListener('keydown', function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey || e.target.tagName === 'SELECT') return;
    const keys = { ArrowRight: function () { go(at + 1); }, ArrowLeft: function () { go(at - 1); },
                   Home: function () { go(0); }, End: function () { go(n - 1); }, ' ': play };
    if (!keys[e.key]) return;
    e.preventDefault();
    keys[e.key]();
  });
  // "index.html#12" opens on step 12.
  const asked = Number(location.hash.slice(1));
  const first = location.hash.length > 1 && Number.isInteger(asked) ? asked - D.steps[0].step : D.start;
  show(first >= 0 && first < n ? first : D.start);
})();
</script>
</body>
</html>
)HTML";

}  // namespace

std::string markdown_html(std::string_view markdown) {
  std::string html;
  const int rc = md_html(
      markdown.data(), MD_SIZE(markdown.size()),
      [](const MD_CHAR* text, MD_SIZE size, void* out) { static_cast<std::string*>(out)->append(text, size); }, &html,
      MD_FLAG_NOHTML | MD_FLAG_TABLES | MD_FLAG_STRIKETHROUGH, 0);
  if (rc != 0) throw InputError("md4c could not convert the lesson's Markdown to HTML");
  return neutralize_urls(html);
}

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string script_safe_json(const Json& data) {
  const std::string text = data.dump(-1, ' ', false, Json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') out += "\\u003c";
    else if (c == '>') out += "\\u003e";
    else if (c == '&') out += "\\u0026";
    else out += c;
  }
  return out;
}

std::string lesson_page(std::string_view title, std::string_view intro_html, const Json& data) {
  const std::string esc_title = html_escape(title), json = script_safe_json(data);
  const std::string w = std::to_string(data.at("size").at(0).get<int>()), h = std::to_string(data.at("size").at(1).get<int>());
  const std::array<std::pair<std::string_view, std::string_view>, 5> fills = {
      {{"@TITLE@", esc_title}, {"@INTRO@", intro_html}, {"@DATA@", json}, {"@W@", w}, {"@H@", h}}};
  // One pass over the template, so text filled in is never searched for markers.
  std::string out;
  std::size_t i = 0;
  while (i < kPage.size()) {
    const std::size_t at = kPage.find('@', i);
    if (at == std::string_view::npos) break;
    out.append(kPage.substr(i, at - i));
    bool filled = false;
    for (const auto& [marker, value] : fills)
      if (kPage.substr(at, marker.size()) == marker) {
        out.append(value);
        i = at + marker.size();
        filled = true;
        break;
      }
    if (!filled) out += '@', i = at + 1;
  }
  out.append(kPage.substr(i));
  return out;
}

}  // namespace sw::vis
