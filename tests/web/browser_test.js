// The web game end to end in headless Chromium (scripts/check-web-game runs it): the page served
// with the COOP/COEP headers (scripts/serve-web), driven with real mouse events, checked through
// its status (--status-file, read from the page's file system) and screenshots; any console
// error fails it. Usage: node browser_test.js PAGE_DIR WORK_DIR
'use strict';
const puppeteer = require('puppeteer-core');
const {spawn, execFileSync} = require('child_process');
const fs = require('fs');
const path = require('path');

const [pageDir, work] = process.argv.slice(2);
const repo = path.resolve(__dirname, '..', '..');
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

function check(cond, message) {
  if (!cond) throw new Error(message);
  console.log('ok: ' + message);
}

// scripts/serve-web on a free port; resolves to its address.
function serve(...flags) {
  const server = spawn('python3', [path.join(repo, 'scripts/serve-web'), pageDir, '--port', '0', ...flags],
                       {stdio: ['ignore', 'pipe', 'inherit']});
  return new Promise((resolve, reject) => {
    server.stdout.on('data', (d) => {
      const m = /http:\/\/\S+/.exec(String(d));
      if (m) resolve({server, url: m[0]});
    });
    server.on('exit', (code) => reject(new Error(`serve-web exited (${code})`)));
  });
}

// Pixels of the table view (left of the panel) that differ by more than 8 % (ImageMagick).
function differingPixels(a, b, crop = '960x720+0+0') {
  try {
    execFileSync('compare', ['-metric', 'AE', '-fuzz', '8%', `${a}[${crop}]`, `${b}[${crop}]`, 'null:'],
                 {stdio: ['ignore', 'ignore', 'pipe']});
    return 0;
  } catch (e) {
    return Math.round(parseFloat(String(e.stderr).split(/\s/)[0]));
  }
}

class Game {
  constructor(page, errors) { this.page = page; this.errors = errors; this.status = null; }

  async read() {
    try {
      return await this.page.evaluate(() => JSON.parse(Module.FS.readFile('/status.json', {encoding: 'utf8'})));
    } catch (e) {
      return null;  // not written yet, or the page is navigating (the service worker's reload)
    }
  }

  async wait(pred, seconds, what) {
    const end = Date.now() + seconds * 1000;
    while (Date.now() < end) {
      if (this.errors.length) throw new Error(`console error while waiting for ${what}: ${this.errors[0]}`);
      const s = await this.read();
      if (s && pred(s)) return (this.status = s);
      await sleep(50);
    }
    throw new Error(`timed out after ${seconds} s waiting for ${what}; last status: ${JSON.stringify(await this.read())}`);
  }

  async clickWidget(label) {
    // A new popup lays itself out over its first frames: wait until the widget stays put.
    let w = null;
    for (const end = Date.now() + 10000; Date.now() < end;) {
      const seen = (await this.wait((s) => label in s.widgets, 10, `the widget ${label}`)).widgets[label];
      if (w && seen.every((v, i) => v === w[i])) break;
      w = seen;
      await sleep(300);
    }
    await this.page.mouse.move((w[0] + w[2]) / 2, (w[1] + w[3]) / 2);
    await sleep(100);
    await this.page.mouse.down();
    await sleep(60);
    await this.page.mouse.up();
    await sleep(300);
  }

  async screenshot(name) {
    const file = path.join(work, name);
    await this.page.screenshot({path: file});
    return file;
  }
}

async function open(browser, url, errors, page = null, desktop = true) {
  page = page || await browser.newPage();
  if (desktop) await page.setViewport({width: 1280, height: 720});
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
    fs.appendFileSync(path.join(work, 'console.txt'), `${m.type()}: ${m.text()}\n`);
  });
  page.on('pageerror', (e) => {
    errors.push(String(e));
    fs.appendFileSync(path.join(work, 'console.txt'), `pageerror: ${e.stack || e}\n`);
  });
  const start = Date.now();
  await page.goto(url);
  await page.bringToFront();
  const g = new Game(page, errors);
  await g.wait((s) => s.frames >= 1, 30, 'the first frame');
  return {g, page, firstFrameMs: Date.now() - start};
}

async function controls(browser, base, errors) {
  const {g, page, firstFrameMs} = await open(browser, `${base}?status=1&seed=3&game=8ball`, errors);
  console.log(`navigation to the first frame: ${firstFrameMs} ms`);
  check(await page.evaluate(() => self.crossOriginIsolated), 'the page is cross-origin isolated (threads)');
  let s = await g.wait((s) => s.phase === 'shoot' && !s.busy, 30, 'the break');
  check(s.info[0] === 'Player 1 to break', 'the information bar says who breaks');
  const rack = await g.screenshot('1-rack.png');
  const heading0 = s.heading_deg;
  // Hold the right button and move horizontally: the aim turns; release: the strike.
  await page.mouse.move(480, 400);
  await page.mouse.down({button: 'right'});
  for (let x = 484; x <= 520; x += 4) {
    await page.mouse.move(x, 400);
    await sleep(30);
  }
  s = await g.wait((s) => s.shots === 0 && Math.abs(s.heading_deg - heading0) > 1, 10, 'the aim to turn');
  check(s.heading_deg < heading0, `moving right turns the aim right (${heading0} -> ${s.heading_deg} deg)`);
  const before = s.positions;
  await page.mouse.up({button: 'right'});
  await g.wait((s) => s.shots === 1, 10, 'the strike on release');
  check(true, 'releasing the right button strikes');
  const f0 = g.status.frames, t0 = Date.now();
  await sleep(2000);
  const fps = ((await g.read()).frames - f0) / ((Date.now() - t0) / 1000);
  console.log(`frame rate during the break at 1280x720: ${fps.toFixed(1)} fps`);
  s = await g.wait((s) => !s.moving && !s.busy, 60, 'the balls to stop');
  check(s.last_shot.startsWith('Player 1 broke'), `the information bar reports the break: ${s.last_shot}`);
  const moved = Object.keys(before).filter((id) => !s.positions[id] ||
      Math.hypot(s.positions[id][0] - before[id][0], s.positions[id][1] - before[id][1]) > 0.01).length;
  check(moved >= 5, `the break moved ${moved} balls (the game's positions)`);
  const broken = await g.screenshot('2-after-break.png');
  const changed = differingPixels(rack, broken);
  check(changed > 2000, `the table changed from the rack (${changed} pixels)`);

  const overhead = await g.screenshot('3-overhead.png');
  await g.clickWidget('Change View');
  await g.wait((s) => s.view === 'cueball', 10, 'the cue-ball view');
  await sleep(2500);  // the camera glides over
  const cueview = await g.screenshot('4-cue-ball-view.png');
  const viewed = differingPixels(overhead, cueview);
  check(viewed > 20000, `Change View changes the image (${viewed} pixels)`);
  await g.clickWidget('Change View');
  await g.wait((s) => s.view === 'overhead', 10, 'the overhead view again');

  await page.keyboard.press('v');
  await g.wait((s) => s.view === 'cueball', 10, 'the cue-ball view by the V key');
  await page.keyboard.press('v');
  await g.wait((s) => s.view === 'overhead', 10, 'the overhead view by the V key');
  check(true, 'the V key changes the view too');

  await g.clickWidget('Sound');
  await g.wait((s) => s.sound === false, 10, 'the sound off');
  check(true, 'the Sound checkbox turns the sound off');
  await g.clickWidget('Sound');
  await g.wait((s) => s.sound === true, 10, 'the sound on');
  check(true, 'and on again');

  await g.clickWidget('Restart');
  await g.clickWidget('Yes, restart');
  s = await g.wait((s) => s.game_number === 1 && s.shots === 0, 10, 'the new rack');
  check(s.balls_on_table === 15 && s.info[0].endsWith('to break'), 'Restart racks the balls again');
  await g.screenshot('5-restarted.png');

  // Hint thinks on a worker thread: the page's animation frames go on meanwhile (a decision on
  // the page's own thread would be made within one frame, the page still until it is).
  await page.evaluate(() => {
    window.frameGaps = [];
    window.framesThinking = 0;
    let last = performance.now();
    const until = last + 4000;
    const tick = (now) => {
      window.frameGaps.push(now - last);
      last = now;
      try {
        if (JSON.parse(Module.FS.readFile('/status.json', {encoding: 'utf8'})).thinking) ++window.framesThinking;
      } catch (e) {}
      if (now < until) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const aimed = s.heading_deg;
  await g.clickWidget('Hint');
  s = await g.wait((s) => !s.thinking && s.heading_deg !== aimed, 10, 'the hint');
  await sleep(4000);
  const slowest = Math.round(Math.max(...await page.evaluate(() => window.frameGaps)));
  const thinking = await page.evaluate(() => window.framesThinking);
  check(thinking >= 2 && slowest < 500,
        `the page draws on while Hint thinks (aim ${aimed} -> ${s.heading_deg} deg; ${thinking} animation ` +
        `frames while it thought, the slowest ${slowest} ms)`);
  await page.close();
}


// Strikes with a right click (press and release, no motion) and waits for the balls to stop.
async function strike(g) {
  await g.page.mouse.move(480, 400);
  await g.page.mouse.down({button: 'right'});
  await sleep(60);
  await g.page.mouse.up({button: 'right'});
  const shots = g.status.shots;
  await g.wait((s) => s.shots === shots + 1, 10, 'the strike');
  return g.wait((s) => !s.moving && !s.busy, 60, 'the balls to stop');
}

// The desktop build's engine (coolaaber-cli simulate) plays the link's stroke from its position:
// the web page's balls must rest at the same numbers, bit for bit (both print round-trip decimals).
function nativeAgrees(link, webPositions) {
  const cli = path.join(repo, 'build/release/src/cli/coolaaber-cli');
  if (!fs.existsSync(cli)) return console.log(`skipped: the native comparison (no ${cli})`);
  const shot = JSON.parse(Buffer.from(link.split('#shot=1.')[1].split('.')[1], 'base64url').toString());
  const params = Object.fromEntries(Object.entries(shot.params).filter(([, v]) => v !== null));
  const balls = Object.entries(shot.state.positions).map(([id, pos]) => ({id: Number(id), pos}));
  const out = JSON.parse(execFileSync(cli, ['simulate'], {
    input: JSON.stringify({table: shot.table, params, balls, strike: shot.stroke})}));
  const native = Object.fromEntries(out.final.filter((b) => b.pos !== null).map((b) => [String(b.id), b.pos]));
  const differ = Object.keys(native).filter((id) => JSON.stringify(native[id]) !== JSON.stringify(webPositions[id]));
  check(differ.length === 0 && Object.keys(native).length === Object.keys(webPositions).length,
        `the native engine puts every ball where the page does, bit for bit (${Object.keys(native).length} balls)`);
}

// The game is kept in the browser's storage as the balls stop: a reload resumes it.
async function resumeAndLinks(browser, base, errors) {
  let {g, page} = await open(browser, `${base}?status=1&seed=5&game=8ball`, errors);
  await g.wait((s) => s.phase === 'shoot' && !s.busy, 30, 'the break');
  const after = await strike(g);
  await sleep(1500);  // the IndexedDB write after the shot
  ({g} = await open(browser, `${base}?status=1`, errors, page));
  let s = await g.wait((s) => s.shots === after.shots, 10, 'the resumed game');
  check(JSON.stringify(s.positions) === JSON.stringify(after.positions),
        'a reload resumes the game: the same shots and every ball where it was');

  // Copy shot link: the last shot (the break), as the page's address with the shot as its
  // fragment; opened, it plays that shot.
  await page.browserContext().overridePermissions(new URL(base).origin,
                                                  ['clipboard-read', 'clipboard-write', 'clipboard-sanitized-write']);
  await g.clickWidget('Copy shot link');
  const link = await page.evaluate(() => navigator.clipboard.readText());
  check(/coolaaber\.html\?status=1#shot=1\./.test(link), `Copy shot link copies the page's address with the shot: ${link.slice(0, 60)}...`);
  const other = await open(browser, link, errors);
  s = await other.g.wait((s) => s.shots === 1 && !s.moving && !s.busy, 60, 'the shared shot to play');
  check(JSON.stringify(s.positions) === JSON.stringify(after.positions),
        'the link (the last shot: the break) replays exactly that shot: every ball ends where it did');
  check(s.link_note.startsWith('Opened the shot link'), `the information bar says: ${s.link_note}`);
  nativeAgrees(link, s.positions);
  await other.page.close();

  const bad = link.replace(/#shot=1\.(.)/, (m, c) => `#shot=1.${c === '0' ? '1' : '0'}`);
  const tampered = await open(browser, bad, errors);
  s = await tampered.g.wait((s) => s.link_note !== '', 10, 'the message about the bad link');
  check(s.link_note.startsWith("The page's address does not hold a shot link") && s.phase === 'shoot',
        `a tampered link gives a message, the table stays playable: ${s.link_note}`);
  await tampered.page.close();
  await page.close();
}

// Two computer players (level 1) play a game of 8-ball to its end.
async function computerGame(browser, base, errors) {
  const start = Date.now();
  const {g, page} = await open(browser, `${base}?status=1&seed=11&game=8ball&players=ai:1,ai:1&playback-speed=0`, errors);
  const s = await g.wait((s) => s.winner !== null, 300, 'the end of the game');
  check(s.phase === 'game_over' && s.info[0] === `${s.winner} wins!`,
        `two computer players finish the game: ${s.info[0]} after ${s.shots} shots (${((Date.now() - start) / 1000).toFixed(1)} s)`);
  await g.screenshot('6-computer-game-over.png');
  await page.close();
}

// A phone in landscape (touch, mobile emulation): one finger drags the aim round, the panel's
// Strike plays the shot at the Power set.
async function touch(browser, base, errors) {
  const page = await browser.newPage();
  const dpr = 2;  // the canvas has the device's pixels; the page's coordinates are CSS pixels
  await page.setViewport({width: 844, height: 390, isMobile: true, hasTouch: true, deviceScaleFactor: dpr});
  const {g} = await open(browser, `${base}?status=1&seed=4&game=9ball`, errors, page, false);
  let s = await g.wait((s) => s.phase === 'shoot' && !s.busy && 'Strike' in s.widgets, 30, 'the break');
  const heading0 = s.heading_deg;
  await page.touchscreen.touchStart(250, 200);
  for (let x = 254; x <= 290; x += 6) {
    await page.touchscreen.touchMove(x, 200);
    await sleep(30);
  }
  await page.touchscreen.touchEnd();
  s = await g.wait((s) => Math.abs(s.heading_deg - heading0) > 1, 10, 'the aim to turn');
  await sleep(300);
  check((await g.read()).shots === 0, `a finger drags the aim round without striking (${heading0} -> ${s.heading_deg} deg)`);
  await g.screenshot('7-phone-aimed.png');
  check(s.window[0] === 844 * dpr && s.window[1] === 390 * dpr, `the canvas has the screen's pixels (${s.window})`);
  const w = s.widgets.Strike.map((v) => v / dpr);
  check(w[2] <= 844 && w[3] <= 390 && w[3] - w[1] >= 24,
        `the Strike button is on the phone's screen, big enough to tap (${w.map(Math.round)} CSS px)`);
  await page.touchscreen.tap((w[0] + w[2]) / 2, (w[1] + w[3]) / 2);
  s = await g.wait((s) => s.shots === 1, 10, 'the strike');
  check(Math.abs(s.heading_deg - heading0) > 1, 'tapping Strike plays the shot as aimed');
  await g.wait((s) => !s.moving && !s.busy, 60, 'the balls to stop');
  await g.screenshot('8-phone-after-break.png');
  await page.close();
}

// A phone upright (390×844 CSS px at 3 device pixels each, touch): the table above, upright,
// the panel below it full width; a finger moves the ball in hand where it points and drags the
// aim round; Strike, at the panel's foot, plays the shot and the balls move.
async function portraitTouch(browser, base, errors) {
  const page = await browser.newPage();
  const dpr = 3;
  await page.setViewport({width: 390, height: 844, isMobile: true, hasTouch: true, deviceScaleFactor: dpr});
  const {g} = await open(browser, `${base}?status=1&seed=5&game=9ball`, errors, page, false);
  let s = await g.wait((s) => s.phase === 'shoot' && !s.busy && 'Strike' in s.widgets, 30, 'the break');
  await g.screenshot('9-portrait-rack.png');
  const [vw, vh] = s.table_view.map((v) => v / dpr);
  check(s.window[0] === 390 * dpr && vw === 390 && s.panel_height > 0 && vh + s.panel_height / dpr === 844,
        `upright, the table view (${vw}x${vh} CSS px) is above the panel (${s.panel_height / dpr} CSS px tall, full width)`);
  const cue = s.ball_px['0'].map((v) => v / dpr), rack = s.ball_px['9'].map((v) => v / dpr);
  check(cue[1] > rack[1] && Math.abs(cue[0] - rack[0]) < 20 && cue[1] < vh && rack[1] > 0,
        `the table stands upright in the view, the break from the bottom (cue ball at ${cue.map(Math.round)}, the 9 at ${rack.map(Math.round)})`);
  // The ball in hand follows the finger: 30 CSS px to the left and back down the screen.
  const before = s.cue_ball;
  await page.touchscreen.touchStart(cue[0], cue[1]);
  for (let k = 1; k <= 6; ++k) {
    await page.touchscreen.touchMove(cue[0] - 5 * k, cue[1] + 2 * k);
    await sleep(40);
  }
  await page.touchscreen.touchEnd();
  s = await g.wait((s) => s.cue_ball && s.cue_ball[1] !== before[1], 10, 'the ball in hand to move');
  const put = s.ball_px['0'].map((v) => v / dpr);
  check(Math.hypot(put[0] - (cue[0] - 30), put[1] - (cue[1] + 12)) < 3 && s.cue_ball[1] > before[1],
        `a finger moves the ball in hand to where it points (${put.map(Math.round)} CSS px, north on the table is left on the screen)`);
  const heading0 = s.heading_deg;
  const y = vh * 0.35;  // clear of the ball in hand
  await page.touchscreen.touchStart(150, y);
  for (let x = 154; x <= 190; x += 6) {
    await page.touchscreen.touchMove(x, y);
    await sleep(30);
  }
  await page.touchscreen.touchEnd();
  s = await g.wait((s) => Math.abs(s.heading_deg - heading0) > 1, 10, 'the aim to turn');
  await sleep(300);
  check((await g.read()).shots === 0, `a finger drags the aim round without striking (${heading0} -> ${s.heading_deg} deg)`);
  const w = s.widgets.Strike.map((v) => v / dpr);
  check(w[1] >= vh && w[3] <= 844 && w[3] - w[1] >= 36 && w[2] - w[0] >= 150,
        `the Strike button is in the panel under the table, big enough to tap (${w.map(Math.round)} CSS px)`);
  // A finger drags the panel's middle (information, spin, elevation, the game's buttons) up.
  const restart0 = s.widgets.Restart[1] / dpr;
  const middleY = vh + (w[1] - vh) * 0.6;
  await page.touchscreen.touchStart(320, middleY);  // right of the tip picture: no control there
  for (let k = 1; k <= 8; ++k) {
    await page.touchscreen.touchMove(320, middleY - 10 * k);
    await sleep(30);
  }
  await page.touchscreen.touchEnd();
  s = await g.wait((s) => s.widgets.Restart[1] / dpr < restart0 - 40, 10, 'the panel to scroll');
  check(s.shots === 0, `a finger scrolls the panel under the table (Restart from y ${Math.round(restart0)} to ${Math.round(s.widgets.Restart[1] / dpr)} CSS px)`);
  await g.screenshot('10-portrait-aimed.png');
  const aimed = s;
  await page.touchscreen.tap((w[0] + w[2]) / 2, (w[1] + w[3]) / 2);
  s = await g.wait((s) => s.shots === 1 && s.moving, 10, 'the strike');
  await sleep(400);
  await g.screenshot('11-portrait-moving.png');
  s = await g.wait((s) => !s.moving && !s.busy, 90, 'the balls to stop');
  const moved = Object.keys(aimed.positions).filter((id) => !(id in s.positions) ||
      Math.hypot(s.positions[id][0] - aimed.positions[id][0], s.positions[id][1] - aimed.positions[id][1]) > 0.01);
  check(moved.length >= 5 && s.last_shot !== '',
        `tapping Strike plays the shot: ${moved.length} balls moved (${s.last_shot})`);
  await g.screenshot('12-portrait-after-break.png');
  await page.close();
}

// A host without the two headers: the service worker adds them (one reload), and keeps the game
// for offline play.
async function withoutHeaders(browser, errors) {
  const {server, url} = await serve('--no-isolation');
  try {
    const {g, page} = await open(browser, `${url}?status=1&game=9ball`, errors);
    check(await page.evaluate(() => self.crossOriginIsolated),
          'without the headers the service worker adds them: the game runs with threads');
    await g.wait((s) => s.phase === 'shoot', 30, 'the rack');
    await page.setOfflineMode(true);
    const again = await open(browser, `${url}?status=1&game=9ball`, errors, page);
    check(again.g.status.frames >= 1, 'offline, the page plays from the service worker\'s cache');
    await page.setOfflineMode(false);
    await page.close();
  } finally {
    server.kill();
  }
}

// ---- Without threads: the fallback build (coolaaber-nothreads.js) and its thinking between frames.

// Two level-5 computer players play a game of 8-ball to its end; in the page, each animation frame
// notes whether the computer is thinking: the decisions' times and the gaps between frames meanwhile.
async function levelFiveGame(browser, url, errors, screenshot, page = null) {
  const opened = await open(browser, `${url}?status=1&seed=11&game=8ball&players=ai:5,ai:5&playback-speed=0`,
                            errors, page);
  await opened.g.screenshot(screenshot);
  await opened.page.evaluate(() => {
    // gaps: between two animation frames while the computer thinks.
    window.thinkingSeen = {spans: [], gaps: []};
    // since: when the thinking began (-1: before the first frame seen, a span not timed).
    let last = performance.now(), since = null, first = true;
    const tick = (now) => {
      let thinking = false;
      try {
        thinking = JSON.parse(Module.FS.readFile('/status.json', {encoding: 'utf8'})).thinking;
      } catch (e) {}
      if (since !== null) window.thinkingSeen.gaps.push(now - last);
      if (thinking && since === null) since = first ? -1 : now;
      if (!thinking && since !== null) {
        if (since >= 0) window.thinkingSeen.spans.push(now - since);
        since = null;
      }
      first = false;
      last = now;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  await opened.g.wait((s) => s.winner !== null, 600, 'the end of a level-5 game');
  const seen = await opened.page.evaluate(() => window.thinkingSeen);
  const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
  const longest = [...seen.gaps].sort((a, b) => b - a);
  return {...opened, spans: seen.spans, slowestGap: longest[0], longestGaps: longest.slice(0, 5),
          medianSpan: median(seen.spans), medianGap: median(seen.gaps), frames: seen.gaps.length};
}

// A host without the two headers and without a service worker (bypassed, as where none can run):
// the page loads the fallback, says so, plays, and keeps drawing while the computer thinks.
async function withoutThreads(browser, isolatedUrl, errors) {
  const threaded = await levelFiveGame(browser, isolatedUrl, errors, '9-level-5-threads.png');
  await threaded.page.close();  // its last status stays in threaded.g.status
  const {server, url} = await serve('--no-isolation');
  try {
    const page = await browser.newPage();
    await page.setBypassServiceWorker(true);
    const run = await levelFiveGame(browser, url, errors, '10-level-5-without-threads.png', page);
    check(!(await page.evaluate(() => self.crossOriginIsolated)) &&
          await page.evaluate(() => !!document.querySelector('script[src="coolaaber-nothreads.js"]')),
          'without the headers and the service worker the page loads the build without threads');
    const notice = await page.evaluate(() => document.getElementById('no-threads').textContent);
    check(notice.startsWith('Playing without threads'), `the page says so: ${notice.slice(0, 60)}...`);
    await run.g.screenshot('11-without-threads-game-over.png');
    const ms = (x) => `${Math.round(x)} ms`;
    console.log(`level-5 decisions, threads: ${threaded.spans.map(ms)}; without: ${run.spans.map(ms)}`);
    console.log(`frames while thinking: the 5 longest gaps ${run.longestGaps.map(ms)}, median ${ms(run.medianGap)} ` +
                `without threads; ${threaded.longestGaps.map(ms)}, median ${ms(threaded.medianGap)} with`);
    console.log(`median level-5 decision: ${ms(run.medianSpan)} without threads, ${ms(threaded.medianSpan)} ` +
                `with (${(run.medianSpan / threaded.medianSpan).toFixed(2)}x)`);
    // A decision made on the page's own thread would stop the frames for all of it (1.3-4 s here
    // after the break). The longest gaps, with threads too, are the frames that draw the table
    // (SwiftShader) and the machine's load; the median is the page's usual pace.
    check(run.spans.length >= 3 && run.frames >= 3 * run.spans.length && run.slowestGap < 1000 &&
          run.medianGap <= 34,
          `the page draws on while the computer thinks without threads (${run.frames} animation frames ` +
          `while it thought, the median gap ${ms(run.medianGap)}, the longest ${ms(run.slowestGap)}; ` +
          `with threads ${ms(threaded.medianGap)}, ${ms(threaded.slowestGap)})`);
    const [a, b] = [threaded.g.status, run.g.status];
    check(b.phase === 'game_over' && b.winner === a.winner && b.shots === a.shots &&
          JSON.stringify(b.positions) === JSON.stringify(a.positions),
          `without threads the level-5 game is the same, to its end: ${b.info[0]} after ${b.shots} shots, ` +
          'every ball where the threaded page left it');
    // Hint thinks the same way.
    const human = await open(browser, `${url}?status=1&seed=3&game=8ball`, errors, page);
    const s = await human.g.wait((s) => s.phase === 'shoot' && !s.busy, 30, 'the break');
    await human.g.clickWidget('Hint');
    const hinted = await human.g.wait((t) => !t.thinking && t.heading_deg !== s.heading_deg, 60, 'the hint');
    check(!(await page.evaluate(() => self.crossOriginIsolated)),
          `Hint works without threads (aim ${s.heading_deg} -> ${hinted.heading_deg} deg)`);
    // Restart while the computer thinks: its thinking is finished first (as a thread is waited
    // for), then the rack is new and the computers play on.
    const again = await open(browser, `${url}?status=1&seed=12&game=8ball&players=ai:5,ai:5&playback-speed=0`,
                             errors, page);
    await again.g.wait((t) => t.shots >= 1, 60, 'the break');
    await again.g.clickWidget('Restart');  // the dialog opens; the computers play on behind it
    await sleep(600);
    const yes = (await again.g.read()).widgets['Yes, restart'];
    const shots = (await again.g.read()).shots;
    const thinking = await again.g.wait((t) => t.thinking && t.shots > shots, 60, 'a new decision');
    await page.mouse.click((yes[0] + yes[2]) / 2, (yes[1] + yes[3]) / 2, {delay: 60});
    const restarted = await again.g.wait((t) => t.game_number === 1 && t.shots === 0, 60, 'the new rack');
    await again.g.wait((t) => t.game_number === 1 && t.shots >= 1, 60, 'the break of the new rack');
    check(restarted.balls_on_table === 15,
          `Restart while the computer thinks (shot ${thinking.shots + 1}) racks again, and it plays on`);
    await page.close();
  } finally {
    server.kill();
  }
}

(async () => {
  fs.mkdirSync(work, {recursive: true});
  const {server, url} = await serve();
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
           '--autoplay-policy=no-user-gesture-required', '--window-size=1280,720'],
  });
  const errors = [];
  try {
    const only = process.env.WEB_TEST_ONLY || '';
    const run = (name) => !only || only.split(',').includes(name);
    if (run('controls')) await controls(browser, url, errors);
    if (run('resume')) await resumeAndLinks(browser, url, errors);
    if (run('computer')) await computerGame(browser, url, errors);
    if (run('touch')) await touch(browser, url, errors);
    if (run('portrait')) await portraitTouch(browser, url, errors);
    if (run('headers')) await withoutHeaders(browser, errors);
    if (run('nothreads')) await withoutThreads(browser, url, errors);
    check(errors.length === 0, 'no console errors');
  } finally {
    await browser.close();
    server.kill();
  }
})().catch((e) => {
  console.error('FAILED: ' + (e.stack || e));
  process.exit(1);
});
