// The web page's figures in headless Chromium (SwiftShader), medians of a few runs:
// navigation to the first frame, the frame rate during the 8-ball break at 1280x720, and the
// level-5 computer player's decision time in the page (the status's "thinking", on its worker
// thread). Needs the web build and scripts/check-web-game's puppeteer-core:
//   NODE_PATH=build/web-test/node_modules node bench/web_page.js build/web/src/app [shots]
'use strict';
const puppeteer = require('puppeteer-core');
const {spawn} = require('child_process');
const path = require('path');

const [pageDir, shotsArg] = process.argv.slice(2);
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];

async function status(page) {
  try {
    return await page.evaluate(() => JSON.parse(Module.FS.readFile('/status.json', {encoding: 'utf8'})));
  } catch (e) {
    return null;
  }
}

async function until(page, pred, seconds) {
  for (const end = Date.now() + seconds * 1000; Date.now() < end; await sleep(20)) {
    const s = await status(page);
    if (s && pred(s)) return s;
  }
  throw new Error('timed out');
}

(async () => {
  const server = spawn('python3', [path.join(__dirname, '..', 'scripts/serve-web'), pageDir, '--port', '0'],
                       {stdio: ['ignore', 'pipe', 'inherit']});
  const base = await new Promise((r) => server.stdout.on('data', (d) => r(/http:\/\/\S+/.exec(String(d))[0])));
  const browser = await puppeteer.launch({executablePath: '/usr/bin/chromium', args: [
    '--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox']});
  try {
    const first = [], fps = [];
    for (let run = 0; run < 3; ++run) {
      const page = await browser.newPage();
      await page.setViewport({width: 1280, height: 720});
      const t0 = Date.now();
      await page.goto(`${base}?status=1&game=8ball&seed=${run + 1}`);
      let s = await until(page, (s) => s.frames >= 1, 60);
      first.push(Date.now() - t0);
      s = await until(page, (s) => s.phase === 'shoot' && !s.busy, 60);
      await page.mouse.move(480, 400);
      await page.mouse.down({button: 'right'});
      await page.mouse.up({button: 'right'});
      s = await until(page, (s) => s.shots === 1, 10);
      const f0 = s.frames, t1 = Date.now();
      await sleep(2000);
      fps.push(((await status(page)).frames - f0) / ((Date.now() - t1) / 1000));
      await page.close();
    }
    console.log(`navigation to the first frame: median ${median(first)} ms (${first.join(', ')})`);
    console.log(`frame rate during the break at 1280x720: median ${median(fps).toFixed(1)} fps (${fps.map((f) => f.toFixed(1)).join(', ')})`);

    const shots = Number(shotsArg || 7);
    const page = await browser.newPage();
    await page.setViewport({width: 1280, height: 720});
    await page.goto(`${base}?status=1&game=9ball&seed=5&players=ai:5,ai:5&playback-speed=0`);
    let s = await until(page, (s) => s.frames >= 1, 60);
    const decide = [];
    while (decide.length < shots && !s.winner) {
      s = await until(page, (x) => x.thinking || x.winner, 120);
      const t0 = Date.now();
      s = await until(page, (x) => !x.thinking, 120);
      if (!s.winner) decide.push((Date.now() - t0) / 1000);
    }
    console.log(`level-5 computer player's decision in the page: median ${median(decide).toFixed(2)} s ` +
                `(${decide.map((d) => d.toFixed(2)).join(', ')})`);
  } finally {
    await browser.close();
    server.kill();
  }
})().catch((e) => { console.error(e); process.exit(1); });
