// Drives Snakemake's HTML report in a headless browser as a reader would, then replaces the page
// with a JSON account of what it saw (<pre id="report-check">), which `chromium --dump-dom` prints.
// tests/test_workflow.py appends this script to a copy of the report; it uses the report app's own
// globals (app, categories, results) only to learn what to click and which view a click opens.
(function () {
  "use strict";
  const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
  const errors = [];
  window.addEventListener("error", (event) => errors.push(String(event.message)));

  // the deepest element of the navigation bar whose text is exactly `label`
  function findByText(label) {
    const all = Array.from(document.querySelectorAll("#app a, #app li, #app span, #app button"));
    const hits = all.filter((el) => el.textContent.trim() === label);
    return hits.length ? hits[hits.length - 1] : null;
  }

  async function click(label) {
    const el = findByText(label);
    if (!el) return false;
    el.click();
    await sleep(50);
    return true;
  }

  // the page's <img> of this result (not, e.g., the report's own logo) has decoded
  async function imageLoads(uri) {
    for (let i = 0; i < 100; i++) {
      const img = Array.from(document.querySelectorAll("#app img")).find((el) => el.src === uri);
      if (img && img.complete) return img.naturalWidth > 0 && img.naturalHeight > 0;
      await sleep(50);
    }
    return false;
  }

  function badLinks() {
    // a link in a single-file report must be in-page, embedded (data:) or absolute
    return Array.from(document.querySelectorAll("#app a[href], #app img[src]"))
      .map((el) => el.getAttribute("href") || el.getAttribute("src"))
      .filter((url) => !/^(#|data:|https?:|mailto:|javascript:)/.test(url));
  }

  const out = { landing: "", landingLists: [], menu: [], categories: {}, results: {}, badLinks: [],
                errors };

  async function run() {
    for (let i = 0; i < 100 && typeof app === "undefined"; i++) await sleep(50);
    await sleep(200);
    out.landing = document.querySelector("#app") ? document.querySelector("#app").innerText : "";
    // numbered lists on the landing page (it has none: Docutils reads an initial, "J. F. Blinn",
    // at the start of a line as a list's letter), each as the HTML that opens it
    // (Docutils marks its enumerated lists with the numbering's kind; the report's own
    // navigation is an <ol> too, without)
    out.landingLists = Array.from(document.querySelectorAll("#app ol"))
      .filter((ol) => /\b(arabic|loweralpha|upperalpha|lowerroman|upperroman)\b/.test(ol.className))
      .map((ol) => ol.outerHTML.slice(0, 120));
    out.badLinks.push(...badLinks());
    for (const category of Object.keys(categories)) {
      app.setView({ navbarMode: "menu" });
      await sleep(50);
      if (findByText(category)) out.menu.push(category);
      const opened = await click(category);
      const subs = Object.keys(categories[category]);
      out.categories[category] = { opened, subcategories: {} };
      for (const sub of subs) {
        if (subs.length > 1) {
          app.setView({ navbarMode: "category", category });
          await sleep(50);
          if (!(await click(sub))) { out.categories[category].subcategories[sub] = null; continue; }
        }
        const listed = document.querySelectorAll("#app tbody tr").length;
        out.categories[category].subcategories[sub] = listed;
        out.badLinks.push(...badLinks());
        for (const path of categories[category][sub]) {
          const entry = results[path];
          const seen = { caption: null, shown: null, mime: entry.mime_type || null };
          app.showResultInfo(path);           // the (i) button: the caption in the navigation bar
          await sleep(50);
          seen.caption = document.querySelector("#app").innerText;
          const captionNode = Array.from(document.querySelectorAll("#app [class*='prose']"));
          seen.captionHtml = captionNode.map((n) => n.innerHTML).join("\n");
          out.badLinks.push(...badLinks());
          if (/\.(png|jpe?g|svg|gif)$/i.test(path)) {   // the eye button: the image in the page
            app.setView({ content: "img", contentPath: entry.data_uri, resultPath: path });
            await sleep(50);
            seen.shown = await imageLoads(entry.data_uri);
          } else {
            seen.shown = typeof entry.data_uri === "string" && entry.data_uri.startsWith("data:")
              && entry.data_uri.length > 64;
          }
          out.results[path] = seen;
        }
      }
    }
  }

  function report() {
    document.documentElement.innerHTML = "";
    const pre = document.createElement("pre");
    pre.id = "report-check";
    pre.textContent = JSON.stringify(out);
    document.documentElement.appendChild(pre);
  }
  window.addEventListener("load", () => {
    run().catch((e) => errors.push("driver: " + String(e))).finally(report);
  });
})();
