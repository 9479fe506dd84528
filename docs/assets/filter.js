// zero's documentation site: a filter above every table of more than 20 rows (the parameters of a
// list kind, the rules): rows that do not contain every word typed are hidden. Runs on each page
// Material shows, also after its instant navigation; loads nothing.
(function () {
  "use strict";
  function setUp() {
    document.querySelectorAll(".md-typeset table").forEach(function (table, n) {
      var body = table.tBodies[0];
      if (!body || body.rows.length <= 20 || table.dataset.filtered) { return; }
      table.dataset.filtered = "1";
      var rows = Array.prototype.slice.call(body.rows);
      var text = rows.map(function (tr) { return tr.textContent.toLowerCase(); });
      var box = document.createElement("input");
      box.type = "search";
      box.className = "zero-filter";
      box.placeholder = "filter these " + rows.length + " rows: key, ID, word…";
      box.setAttribute("aria-label", "filter the table");
      box.id = "zero-filter-" + n;
      var count = document.createElement("span");
      count.className = "zero-filter-count";
      count.textContent = rows.length + " of " + rows.length;
      box.addEventListener("input", function () {
        var words = box.value.toLowerCase().split(/\s+/).filter(Boolean);
        var shown = 0;
        rows.forEach(function (tr, i) {
          var ok = words.every(function (w) { return text[i].indexOf(w) >= 0; });
          tr.hidden = !ok;
          if (ok) { shown += 1; }
        });
        count.textContent = shown + " of " + rows.length;
      });
      var wrap = table.closest(".md-typeset__scrollwrap") || table;
      wrap.parentNode.insertBefore(box, wrap);
      wrap.parentNode.insertBefore(count, wrap);
    });
  }
  if (typeof document$ !== "undefined" && document$.subscribe) {
    document$.subscribe(setUp);  // Material's instant navigation
  } else {
    document.addEventListener("DOMContentLoaded", setUp);
  }
}());
