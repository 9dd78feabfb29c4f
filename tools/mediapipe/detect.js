// MediaPipe Pose (BlazePose, 33 keypoints) on every RGB image of a simcap dataset, in Debian's
// headless chromium, written as COCO keypoint results; scripts/detect_mediapipe is the entry point.
'use strict';

const fs = require('fs');
const http = require('http');
const path = require('path');

const kPoseDir = path.join(__dirname, 'node_modules', '@mediapipe', 'pose');
const kSetupHint = 'run `make setup-mediapipe` in the simcap checkout';
const kModels = {lite: 0, full: 1, heavy: 2};
// One image takes about a second on SwiftShader; a page that hangs (no WebGL) is an error.
const kTimeoutSeconds = 180;

const kHelp = `Usage: scripts/detect_mediapipe DATASET -o DET.json [options]

Runs MediaPipe Pose (BlazePose, 33 keypoints; models from the @mediapipe/pose npm package) in
Debian's headless chromium on every RGB image (camNN/rgb/%06d.png) of a dataset written by
\`simcap render\`, and writes COCO keypoint results: one entry per image where a person was found,
{"image_id", "file_name", "category_id": 1, "keypoints": [x, y, score] x 33, "score"}.
image_id = 1 + frame * cameras + camera (as in the dataset's gt/keypoints_coco.json); x, y are
pixels with the centre of the top-left pixel at (0, 0); a keypoint's score is MediaPipe's
visibility, the person's score the mean of the 33. Nothing is fetched from the network:
chromium only reaches a server this program starts on 127.0.0.1.

Options:
  -o, --output FILE      COCO results JSON to write (written under a temporary name, then renamed)
  --every K              every K-th frame only (0, K, 2K, ...; default 1)
  --cameras A,B          only these cameras (default: all of meta.json "cameras")
  --mode video|images    video (default): each camera's frames in order, MediaPipe tracking the
                         person from one frame to the next as on a video; images: every image on
                         its own, the person detector first (about twice as slow)
  --model NAME           lite | full | heavy (default full)
  --min-confidence C     MediaPipe's minDetectionConfidence (default 0.5)
  --chromium PATH        browser to run (default $CHROMIUM, else /usr/bin/chromium)
  --browser-log          copy the page's console (MediaPipe's log) to stderr
  -q, --quiet            no progress on stderr
  -h, --help             this text

Examples:
  scripts/detect_mediapipe out/studio4 -o out/studio4/mediapipe.json
  scripts/detect_mediapipe out/studio4 -o out/det.json --every 5 --cameras cam00,cam02
  simcap validate out/studio4 --detections out/studio4/mediapipe.json -o out/det-report

Set-up (once): make setup-mediapipe (Debian's chromium + npm ci in tools/mediapipe).`;

class UsageError extends Error {}

function parseArgs(argv) {
  const options = {
    every: 1,
    cameras: null,
    model: 'full',
    mode: 'video',
    minConfidence: 0.5,
    chromium: process.env.CHROMIUM || '/usr/bin/chromium',
    quiet: false,
  };
  const positional = [];
  const value = (i, name) => {
    if (i + 1 >= argv.length) throw new UsageError(`${name} needs a value`);
    return argv[i + 1];
  };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (a === '-h' || a === '--help') {
      options.help = true;
    } else if (a === '-q' || a === '--quiet') {
      options.quiet = true;
    } else if (a === '-o' || a === '--output') {
      options.output = value(i++, a);
    } else if (a === '--every') {
      const text = value(i++, a);
      options.every = Number(text);
      if (!/^[0-9]+$/.test(text) || options.every < 1) {
        throw new UsageError(`--every: expected a whole number >= 1, got '${text}'`);
      }
    } else if (a === '--cameras') {
      options.cameras = value(i++, a).split(',').filter((c) => c.length > 0);
      if (options.cameras.length === 0) throw new UsageError('--cameras: expected names such as cam00,cam02');
    } else if (a === '--model') {
      options.model = value(i++, a);
      if (!(options.model in kModels)) {
        throw new UsageError(`--model: expected lite, full or heavy, got '${options.model}'`);
      }
    } else if (a === '--mode') {
      options.mode = value(i++, a);
      if (options.mode !== 'video' && options.mode !== 'images') {
        throw new UsageError(`--mode: expected video or images, got '${options.mode}'`);
      }
    } else if (a === '--browser-log') {
      options.browserLog = true;
    } else if (a === '--min-confidence') {
      const text = value(i++, a);
      options.minConfidence = Number(text);
      if (text.trim() === '' || !(options.minConfidence >= 0 && options.minConfidence <= 1)) {
        throw new UsageError(`--min-confidence: expected a number in [0, 1], got '${text}'`);
      }
    } else if (a === '--chromium') {
      options.chromium = value(i++, a);
    } else if (a.startsWith('-') && a !== '-') {
      throw new UsageError(`unknown option '${a}' (see --help)`);
    } else {
      positional.push(a);
    }
  }
  if (options.help) return options;
  if (positional.length !== 1) throw new UsageError(`expected one DATASET folder, got ${positional.length} (see --help)`);
  if (!options.output) throw new UsageError('-o DET.json is required (see --help)');
  options.dataset = positional[0];
  return options;
}

// The images to detect on, camera after camera, each camera's frames in order, and the frame
// rate, from meta.json.
function listImages(options) {
  const metaPath = path.join(options.dataset, 'meta.json');
  if (!fs.existsSync(options.dataset)) throw new Error(`${options.dataset}: no such dataset folder`);
  if (!fs.existsSync(metaPath)) {
    throw new Error(`${metaPath}: not found (is ${options.dataset} a dataset written by \`simcap render\`?)`);
  }
  let meta;
  try {
    meta = JSON.parse(fs.readFileSync(metaPath, 'utf8'));
  } catch (e) {
    throw new Error(`${metaPath}: not valid JSON: ${e.message}`);
  }
  const cameras = meta.cameras;
  if (!Array.isArray(cameras) || cameras.length === 0 || !cameras.every((c) => typeof c === 'string' && /^[A-Za-z0-9_.-]+$/.test(c))) {
    throw new Error(`${metaPath}: field "cameras": expected a non-empty list of camera names`);
  }
  const frames = meta.frame_count;
  if (!Number.isInteger(frames) || frames < 1) {
    throw new Error(`${metaPath}: field "frame_count": expected a whole number >= 1`);
  }
  const fps = meta.fps;
  if (typeof fps !== 'number' || !(fps > 0)) throw new Error(`${metaPath}: field "fps": expected a number > 0`);
  if (meta.complete === false) {
    throw new Error(`${metaPath}: the render is not complete ("complete": false); finish it with \`simcap render --resume\``);
  }
  const chosen = options.cameras || cameras;
  for (const c of chosen) {
    if (!cameras.includes(c)) throw new Error(`--cameras: '${c}' is not a camera of ${metaPath} (${cameras.join(', ')})`);
  }
  const images = [];
  cameras.forEach((camera, index) => {
    if (!chosen.includes(camera)) return;
    for (let frame = 0; frame < frames; frame += options.every) {
      const fileName = `${camera}/rgb/${String(frame).padStart(6, '0')}.png`;
      const file = path.join(options.dataset, fileName);
      if (!fs.existsSync(file)) throw new Error(`${file}: not found (meta.json says ${frames} frames)`);
      images.push({imageId: 1 + frame * cameras.length + index, fileName, file, frame, camera});
    }
  });
  return {images, fps};
}

// Serves the page, the pose solution's files and the dataset's images; nothing else.
function startServer(images) {
  const byUrl = new Map(images.map((im) => ['/dataset/' + im.fileName, im.file]));
  const pageHtml = '<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,">' +
    '<script src="/mediapipe/pose.js"></script><script src="/page.js"></script></head><body></body></html>';
  const types = {'.js': 'text/javascript', '.wasm': 'application/wasm', '.png': 'image/png', '.html': 'text/html'};
  const server = http.createServer((req, res) => {
    const url = decodeURIComponent(req.url.split('?')[0]);
    let file = null;
    if (url === '/') {
      res.writeHead(200, {'Content-Type': 'text/html'});
      res.end(pageHtml);
      return;
    } else if (url === '/page.js') {
      file = path.join(__dirname, 'page.js');
    } else if (url.startsWith('/mediapipe/') && /^[A-Za-z0-9_.-]+$/.test(url.slice(11))) {
      file = path.join(kPoseDir, url.slice(11));
    } else if (byUrl.has(url)) {
      file = byUrl.get(url);
    }
    fs.readFile(file || '', (err, data) => {
      if (err) {
        res.writeHead(404);
        res.end();
        return;
      }
      res.writeHead(200, {'Content-Type': types[path.extname(file)] || 'application/octet-stream'});
      res.end(data);
    });
  });
  return new Promise((resolve, reject) => {
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => resolve(server));
  });
}

// simcap's pixel convention from MediaPipe's normalised one: MediaPipe's x in [0, 1] spans the
// image from its left edge to its right edge, so pixel i's centre is at (i + 0.5) / width.
function toResult(image, detection) {
  const keypoints = [];
  let scoreSum = 0;
  for (const [x, y, visibility] of detection.landmarks) {
    keypoints.push(round(x * detection.width - 0.5, 3), round(y * detection.height - 0.5, 3), round(visibility, 4));
    scoreSum += visibility;
  }
  return {
    image_id: image.imageId,
    file_name: image.fileName,
    category_id: 1,
    keypoints,
    score: round(scoreSum / detection.landmarks.length, 4),
  };
}

function round(value, digits) {
  const scale = 10 ** digits;
  return Math.round(value * scale) / scale;
}

function writeAtomically(file, text) {
  fs.mkdirSync(path.dirname(path.resolve(file)), {recursive: true});
  const temp = `${file}.tmp${process.pid}`;
  try {
    fs.writeFileSync(temp, text);
    fs.renameSync(temp, file);
  } catch (e) {
    fs.rmSync(temp, {force: true});
    throw new Error(`${file}: cannot write: ${e.message}`);
  }
}

function loadPuppeteer() {
  if (!fs.existsSync(path.join(kPoseDir, 'pose.js'))) {
    throw new Error(`${kPoseDir}: the MediaPipe Pose package is not installed; ${kSetupHint}`);
  }
  try {
    return require('puppeteer-core');
  } catch (e) {
    throw new Error(`puppeteer-core is not installed in ${__dirname} (${e.message}); ${kSetupHint}`);
  }
}

async function detect(options, images, fps, progress) {
  const puppeteer = loadPuppeteer();
  if (!fs.existsSync(options.chromium)) {
    throw new Error(`${options.chromium}: chromium not found; ${kSetupHint} (or pass --chromium PATH)`);
  }
  const server = await startServer(images);
  const origin = `http://127.0.0.1:${server.address().port}`;
  let browser = null;
  let closing = false;
  const failures = [];
  const blocked = [];
  try {
    browser = await puppeteer.launch({
      executablePath: options.chromium,
      headless: true,
      pipe: true,
      protocolTimeout: kTimeoutSeconds * 1000,
      args: [
        // root in a container: chromium's sandbox needs user namespaces it may not have.
        '--no-sandbox',
        // WebGL without a GPU: MediaPipe's image steps run on SwiftShader.
        '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
        '--force-color-profile=srgb',
        // Nothing may leave the machine: every host name but the loopback fails to resolve,
        // and chromium's own background traffic is off.
        '--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        '--disable-domain-reliability', '--no-pings', '--no-first-run', '--no-default-browser-check',
      ],
    });
  } catch (e) {
    server.close();
    throw new Error(`${options.chromium} failed to start: ${e.message.split('\n')[0]}`);
  }
  browser.on('disconnected', () => {
    if (!closing) failures.push('chromium exited unexpectedly (crash or killed)');
  });
  try {
    const page = await browser.newPage();
    await page.setRequestInterception(true);
    page.on('request', (request) => {
      const url = request.url();
      if (url.startsWith(origin + '/') || url.startsWith('data:') || url.startsWith('blob:')) {
        request.continue();
      } else {
        blocked.push(url);
        request.abort('blockedbyclient');
      }
    });
    if (options.browserLog) page.on('console', (m) => process.stderr.write(`chromium: ${m.text()}\n`));
    page.on('pageerror', (e) => failures.push(`page error: ${e.message}`));
    page.on('error', (e) => failures.push(`page crashed: ${e.message}`));
    const checkFailures = () => {
      if (failures.length > 0) throw new Error(`${failures[0]}`);
      if (blocked.length > 0) throw new Error(`the page tried to reach the network (${blocked[0]}); refused`);
    };
    await page.goto(origin + '/', {waitUntil: 'load'});
    checkFailures();
    const startedAt = process.hrtime.bigint();
    await page.evaluate((o) => window.simcapInit(o), {
      modelComplexity: kModels[options.model],
      minDetectionConfidence: options.minConfidence,
    });
    checkFailures();
    const initSeconds = Number(process.hrtime.bigint() - startedAt) / 1e9;
    const results = [];
    let at = 0;
    const detectStart = process.hrtime.bigint();
    for (let i = 0; i < images.length; ++i) {
      const image = images[i];
      let detection;
      try {
        const mode = i === 0 ? 'track' : options.mode === 'images' ? 'forget' : image.camera !== images[i - 1].camera ? 'restart' : 'track';
        // The dataset's time in video mode; a second between images that are not consecutive.
        at += mode === 'track' && i > 0 ? (1000 * options.every) / fps : 1000;
        detection = await page.evaluate((url, m, t) => window.simcapDetect(url, m, t), '/dataset/' + image.fileName, mode, at);
      } catch (e) {
        checkFailures();
        const reason = /timed out/.test(e.message)
          ? `chromium did not answer within ${kTimeoutSeconds} s (is WebGL available? try --browser-log)`
          : e.message.split('\n')[0];
        throw new Error(`${image.file}: detection failed: ${reason}`);
      }
      checkFailures();
      if (detection.landmarks) {
        if (detection.landmarks.length !== 33) {
          throw new Error(`${image.file}: MediaPipe returned ${detection.landmarks.length} landmarks, expected 33`);
        }
        results.push(toResult(image, detection));
      }
      progress(i + 1, images.length, results.length, image);
    }
    const detectSeconds = Number(process.hrtime.bigint() - detectStart) / 1e9;
    results.sort((a, b) => a.image_id - b.image_id);
    return {results, initSeconds, detectSeconds};
  } finally {
    closing = true;
    await browser.close().catch(() => {});
    server.close();
  }
}

function formatResults(results) {
  if (results.length === 0) return '[]\n';
  return '[\n' + results.map((r) => '  ' + JSON.stringify(r)).join(',\n') + '\n]\n';
}

async function main() {
  let options;
  try {
    options = parseArgs(process.argv.slice(2));
  } catch (e) {
    if (!(e instanceof UsageError)) throw e;
    process.stderr.write(`detect_mediapipe: ${e.message}\n`);
    return 2;
  }
  if (options.help) {
    process.stdout.write(kHelp + '\n');
    return 0;
  }
  let lineOpen = false;
  const log = (text) => {
    if (!options.quiet) process.stderr.write(text);
  };
  try {
    const {images, fps} = listImages(options);
    log(`detect_mediapipe: ${images.length} images of ${options.dataset} (model ${options.model})\n`);
    // As simcap's own progress: one line redrawn each second on a terminal, a line every 5 s in
    // a log, where carriage returns would run the lines together.
    const tty = Boolean(process.stderr.isTTY);
    let lastPrint = 0;
    const progress = (done, total, found, image) => {
      const now = Date.now();
      if (done === total || now - lastPrint > (tty ? 1000 : 5000)) {
        lastPrint = now;
        lineOpen = tty && done !== total;
        log(`${tty ? '\r' : ''}detect_mediapipe: ${done}/${total} images, person in ${found} (${image.camera} frame ${image.frame})${lineOpen ? '' : '\n'}`);
      }
    };
    const {results, initSeconds, detectSeconds} = await detect(options, images, fps, progress);
    writeAtomically(options.output, formatResults(results));
    log(`detect_mediapipe: person found in ${results.length} of ${images.length} images; ` +
      `${(1000 * detectSeconds / images.length).toFixed(1)} ms/image (+ ${initSeconds.toFixed(1)} s start-up) -> ${options.output}\n`);
    return 0;
  } catch (e) {
    process.stderr.write(`${lineOpen ? '\n' : ''}detect_mediapipe: error: ${e.message}\n`);
    return 1;
  }
}

main().then((code) => process.exit(code));
