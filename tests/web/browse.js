// Opens a page in headless Chromium and reports what it says: every console
// message and uncaught exception on stdout, one a line ("log: ...",
// "warning: ...", "error: ..."), until a console message contains the
// --until text (or --timeout seconds pass: exit status 3). Then saves a
// screenshot of the page (--screenshot FILE.png) and lets downloads land in
// --downloads DIR. Drives Chromium through the DevTools protocol on a pipe
// (--remote-debugging-pipe): no port, no package beyond Node.js itself.
//
// node tests/web/browse.js --url URL [--until TEXT] [--timeout S]
//     [--screenshot FILE] [--downloads DIR] [--size WxH] [--chromium PATH]
//     [--choose FILE] [--cpu 1]
//
// --choose gives FILE to the page's file chooser (#file) once the page says
// it showed its first frame. --cpu 1 prints, at the end, the processor time
// the page's renderer process has taken since it started ("cpu: renderer
// process S s", Chromium's ProcessTime metric).
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

function options(argv) {
  const o = { until: "sandbox: stopped", timeout: 60, size: "1280x760", chromium: "chromium",
              choose: "", cpu: "" };
  for (let i = 2; i < argv.length; i += 2) {
    const key = argv[i].replace(/^--/, "");
    if (!(key in o) && !["url", "screenshot", "downloads"].includes(key)) {
      throw new Error("unknown option " + argv[i]);
    }
    o[key] = argv[i + 1];
  }
  if (!o.url) throw new Error("--url is needed");
  return o;
}

function main() {
  const o = options(process.argv);
  const [width, height] = o.size.split("x").map(Number);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), "browse-"));
  const chrome = spawn(o.chromium, [
    "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
    "--no-first-run", "--no-default-browser-check", "--disable-extensions",
    "--user-data-dir=" + profile, "--window-size=" + width + "," + height, "about:blank",
  ], { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
  let chromeErr = "";
  chrome.stderr.on("data", (d) => { chromeErr += d; });

  let nextId = 1;
  const waiting = new Map();
  const handlers = [];
  let pending = "";
  chrome.stdio[4].on("data", (data) => {
    pending += data.toString("utf8");
    let end;
    while ((end = pending.indexOf("\0")) >= 0) {
      const message = JSON.parse(pending.slice(0, end));
      pending = pending.slice(end + 1);
      if (message.id !== undefined && waiting.has(message.id)) {
        const { resolve, reject } = waiting.get(message.id);
        waiting.delete(message.id);
        if (message.error) reject(new Error(JSON.stringify(message.error)));
        else resolve(message.result);
      } else if (message.method) {
        for (const handler of handlers) handler(message);
      }
    }
  });
  function send(method, params, sessionId) {
    const id = nextId++;
    const message = { id, method, params: params || {} };
    if (sessionId) message.sessionId = sessionId;
    chrome.stdio[3].write(JSON.stringify(message) + "\0");
    return new Promise((resolve, reject) => waiting.set(id, { resolve, reject }));
  }

  let finished = false;
  function finish(status) {
    if (finished) return;
    finished = true;
    process.exitCode = status;
    chrome.removeAllListeners("exit");
    chrome.on("exit", () => {
      try {
        fs.rmSync(profile, { recursive: true, force: true, maxRetries: 10 });
      } catch (e) {
        // Chromium's helpers may still write there for a moment: left for the system.
      }
    });
    chrome.kill("SIGKILL");
  }
  const timer = setTimeout(() => {
    console.log("browse: no '" + o.until + "' within " + o.timeout + " s");
    finish(3);
  }, Number(o.timeout) * 1000);
  chrome.on("exit", (code) => {
    if (!finished) {
      console.log("browse: chromium ended (status " + code + ")\n" + chromeErr.slice(-2000));
      clearTimeout(timer);
      finish(2);
    }
  });

  let done;
  const untilSeen = new Promise((resolve) => { done = resolve; });
  handlers.push((m) => {
    if (m.method === "Runtime.consoleAPICalled") {
      const text = m.params.args.map((a) => (a.value !== undefined ? a.value : a.description)).join(" ");
      console.log(m.params.type + ": " + text);
      if (text.includes(o.until)) done();
      if (o.choose && text.includes("first frame")) choose();
    } else if (m.method === "Runtime.exceptionThrown") {
      const d = m.params.exceptionDetails;
      console.log("error: uncaught " + (d.exception ? d.exception.description : d.text));
    } else if (m.method === "Log.entryAdded") {
      console.log(m.params.entry.level + ": [" + m.params.entry.source + "] " + m.params.entry.text);
    }
  });

  let session;
  function choose() {
    (async () => {
      const { root } = await send("DOM.getDocument", {}, session);
      const { nodeId } = await send("DOM.querySelector", { nodeId: root.nodeId, selector: "#file" }, session);
      await send("DOM.setFileInputFiles", { files: [path.resolve(o.choose)], nodeId }, session);
    })().catch((e) => console.log("browse: cannot choose " + o.choose + ": " + e.message));
  }

  (async () => {
    const { targetInfos } = await send("Target.getTargets");
    const page = targetInfos.find((t) => t.type === "page");
    const { sessionId } = await send("Target.attachToTarget", { targetId: page.targetId, flatten: true });
    session = sessionId;
    if (o.downloads) {
      fs.mkdirSync(o.downloads, { recursive: true });
      await send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: path.resolve(o.downloads) });
    }
    await send("Emulation.setDeviceMetricsOverride",
               { width, height, deviceScaleFactor: 1, mobile: false }, sessionId);
    await send("Runtime.enable", {}, sessionId);
    await send("Log.enable", {}, sessionId);
    await send("Page.enable", {}, sessionId);
    await send("Page.navigate", { url: o.url }, sessionId);
    await untilSeen;
    clearTimeout(timer);
    if (o.cpu) {
      await send("Performance.enable", {}, sessionId);
      const { metrics } = await send("Performance.getMetrics", {}, sessionId);
      const cpu = metrics.find((m) => m.name === "ProcessTime");
      console.log("cpu: renderer process " + (cpu ? cpu.value : "unknown") + " s");
    }
    if (o.screenshot) {
      const shot = await send("Page.captureScreenshot", { format: "png" }, sessionId);
      fs.writeFileSync(o.screenshot, Buffer.from(shot.data, "base64"));
    }
    // Give downloads a moment to be written.
    if (o.downloads) await new Promise((r) => setTimeout(r, 500));
    finish(0);
  })().catch((e) => {
    console.log("browse: " + e.message);
    clearTimeout(timer);
    finish(2);
  });
}

main();
