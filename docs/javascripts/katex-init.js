// Typesets the maths on every page with the KaTeX files served by the site itself (docs/javascripts/katex/,
// taken from the npm package katex): the site needs no network. pymdownx.arithmatex (generic mode) wraps inline
// maths as <span class="arithmatex">\(...\)</span> and display maths as <div class="arithmatex">\[...\]</div>;
// only those elements are rendered, so a dollar sign in code or prose is never touched.
(function () {
  "use strict";

  function typeset(root) {
    root.querySelectorAll(".arithmatex").forEach(function (element) {
      var tex = element.textContent.trim();
      var display = element.tagName === "DIV";
      tex = tex.replace(/^\\[(\[]/, "").replace(/\\[)\]]$/, "");
      try {
        katex.render(tex, element, { displayMode: display, throwOnError: true });
      } catch (error) {
        // Keep the source visible and say what failed: the browser test reports console errors.
        console.error("KaTeX could not typeset " + JSON.stringify(tex) + ": " + error.message);
      }
    });
  }

  if (typeof document$ !== "undefined") {
    document$.subscribe(function () { typeset(document); });  // mkdocs-material (also with instant navigation)
  } else {
    document.addEventListener("DOMContentLoaded", function () { typeset(document); });
  }
})();
