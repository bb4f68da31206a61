// The checks of book/browser_check.py, run in each page once it has loaded; resolves to a JSON list of
// [kind, where, detail].  Kinds: overflow, raw TeX, broken image, empty figure.
(async () => {
  const images = [...document.images];
  images.forEach((img) => { img.loading = "eager"; });
  await Promise.all(images.map((img) => img.decode().catch(() => null)));
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) { await MathJax.startup.promise; }
  const findings = [];
  const article = document.querySelector("article.bd-article") || document.querySelector("main") || document.body;
  const where = (el) => {
    let id = el.id ? "#" + el.id : "";
    let cls = typeof el.className === "string" && el.className ? "." + el.className.trim().split(/\s+/).join(".") : "";
    let section = el.closest("section[id]");
    let text = (el.textContent || "").replace(/\s+/g, " ").trim().slice(0, 70);
    return `${el.tagName.toLowerCase()}${id}${cls.slice(0, 60)} in #${section ? section.id : "?"}: "${text}"`;
  };
  const style = getComputedStyle(article);
  const box = article.getBoundingClientRect();
  const left = box.left + parseFloat(style.paddingLeft), right = box.right - parseFloat(style.paddingRight);
  const narrow = window.innerWidth < 600;
  const reported = new Set();
  const isReported = (el) => { for (let p = el.parentElement; p; p = p.parentElement) { if (reported.has(p)) return true; } return false; };
  for (const el of article.querySelectorAll("*")) {
    const container = el.closest("mjx-container");
    if (container && container !== el) continue;      // MathJax internals: the container speaks for them
    if (el.closest("mjx-assistive-mml, script, style, .headerlink")) continue;
    if (el.closest("details:not([open])") && !el.closest("summary")) continue;  // folded: the reader sees none of it
    const rect = el.getBoundingClientRect();
    if (rect.width === 0 && rect.height === 0) continue;  // folded or hidden
    let clipped = false;
    for (let p = el.parentElement; p && p !== article; p = p.parentElement) {
      if (getComputedStyle(p).overflowX !== "visible") { clipped = true; break; }
    }
    if (!clipped && (rect.right > right + 1 || rect.left < left - 1) && !isReported(el)) {
      reported.add(el);
      findings.push(["overflow", where(el), `${Math.round(rect.width)} px wide, column ${Math.round(right - left)} px`]);
      continue;
    }
    const overflowX = getComputedStyle(el).overflowX;
    if (el.matches("span.math")) {
      // Inline math: its scrollWidth counts MathJax's hidden assistive MathML; compare the typeset box instead.
      const inner = el.querySelector("mjx-container");
      const width = inner ? inner.getBoundingClientRect().width : 0;
      if (width > el.clientWidth + 1 && !isReported(el)) {
        reported.add(el);
        findings.push(["overflow", where(el), `inline formula ${Math.round(width)} px in ${el.clientWidth} px`]);
      }
      continue;
    }
    if (overflowX !== "visible" && el.scrollWidth > el.clientWidth + 1 && !isReported(el)) {
      const table = el.matches(".pst-scrollable-table-container, .table-wrapper") || el.querySelector(":scope > table");
      if (narrow && (table || el.matches("pre"))) continue;  // on a phone, tables and code scroll in their frame
      reported.add(el);
      findings.push(["overflow", where(el), `scrolls: ${el.scrollWidth} px of content in ${el.clientWidth} px`]);
    }
  }
  for (const err of document.querySelectorAll("mjx-merror")) {
    findings.push(["raw TeX", where(err.closest("mjx-container") || err), "MathJax error: " + err.textContent.slice(0, 80)]);
  }
  const tex = /\$[^$\s][^$]*\$|\\(frac|begin|end|mathrm|left|right|sqrt|cdot|quad|text|math\w+|[a-z]+\{)|\\\(|\\\[/;
  const walker = document.createTreeWalker(article, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (!parent || parent.closest("pre, code, script, style, mjx-container, textarea, .highlight, .cell_input")) continue;
    const match = node.textContent.match(tex);
    if (match) findings.push(["raw TeX", where(parent), `"${match[0]}" in "${node.textContent.trim().slice(0, 80)}"`]);
  }
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 48;
  const context = canvas.getContext("2d", { willReadFrequently: true });
  for (const img of images) {
    if (!img.complete || img.naturalWidth === 0) { findings.push(["broken image", where(img), img.getAttribute("src")]); continue; }
    if (!img.closest("figure, .cell_output")) continue;
    context.clearRect(0, 0, 48, 48);
    context.drawImage(img, 0, 0, 48, 48);
    const data = context.getImageData(0, 0, 48, 48).data;
    const colours = new Set();
    for (let i = 0; i < data.length; i += 4) colours.add(`${data[i] >> 4},${data[i + 1] >> 4},${data[i + 2] >> 4},${data[i + 3] >> 6}`);
    if (colours.size < 4) findings.push(["empty figure", where(img), `${colours.size} colours in ${img.getAttribute("src")}`]);
  }
  for (const figure of article.querySelectorAll("figure")) {
    if (!figure.querySelector("img, svg, canvas, video")) findings.push(["empty figure", where(figure), "no image"]);
  }
  return JSON.stringify(findings);
})()
