// The HTML of `stepwise lesson export --html`: Markdown to HTML (md4c-html) and the one
// self-contained page (inline CSS, JavaScript and page data; docs/lesson-export.md).
#pragma once
#include <string>
#include <string_view>
#include "input.hpp"

namespace sw::vis {

// Markdown as HTML through md4c-html. Raw HTML in the text is escaped, not passed through, and a
// link or image target with a scheme other than http, https or mailto becomes "#", so lesson text
// cannot run script in the page. Throws InputError if md4c fails.
std::string markdown_html(std::string_view markdown);

// Text for an HTML element or a double-quoted attribute.
std::string html_escape(std::string_view text);

// JSON text safe inside <script type="application/json">: '<', '>' and '&' (which JSON has only
// inside strings) are written as \u escapes, so no "</script>" can end the blob.
std::string script_safe_json(const Json& data);

// The whole page. `data` is the page data (docs/lesson-export.md); the title is escaped here and
// the intro is HTML already (markdown_html).
std::string lesson_page(std::string_view title, std::string_view intro_html, const Json& data);

}  // namespace sw::vis
