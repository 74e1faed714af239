// The page around the explorer (docs/web.md): sizes the canvas in device
// pixels, starts main() once a practice assignment or a share link is in the
// work folder, turns the explorer's written files into downloads and its
// File > Open into the browser's file chooser, shows the current error in the
// bar, wakes the explorer's sleeping loop on input, asks before unsaved edits
// are lost, and offers window.m3055, the test API.
'use strict';
(function () {
  const WORK = '/work';
  const canvas = document.getElementById('canvas');
  const note = document.getElementById('note');
  const message = document.getElementById('message');
  const fileInput = document.getElementById('file');
  const errorLine = document.getElementById('error');
  const errorText = document.getElementById('error-text');
  let started, failed, isReady = false;
  let startError = '';  // why a share or practice link did not open (shown once started)
  const ready = new Promise((resolve, reject) => { started = resolve; failed = reject; });
  ready.then(() => { isReady = true; }, () => {});

  // Emscripten's GLFW listens for gamepads being connected, and a page that
  // listens for them has the browser poll the gamepads 60 times a second
  // (2 % of a core here while the explorer sleeps). The explorer reads no
  // gamepad: those two listeners are not added.
  const addListener = window.addEventListener;
  window.addEventListener = function (type, ...rest) {
    if (type === 'gamepadconnected' || type === 'gamepaddisconnected') return;
    return addListener.call(this, type, ...rest);
  };

  function deviceSize() {
    const dpr = window.devicePixelRatio || 1;
    const rect = canvas.getBoundingClientRect();
    return [Math.max(1, Math.round(rect.width * dpr)), Math.max(1, Math.round(rect.height * dpr))];
  }
  function say(text) { note.textContent = text; note.title = text; }
  function basename(path) { return path.split('/').pop(); }

  // The one place for the current error: the explorer's (its newest error
  // message, explore/current_error.h) or the page's own (a link that did not
  // open), the newer of the two, whole, on its own line under the buttons.
  // Its × hides it until another error comes.
  let explorerError = '';
  function showError(text) {
    errorText.textContent = text;
    errorLine.hidden = !text;
  }
  document.getElementById('error-close').addEventListener('click', () => showError(''));

  // The explorer's loop sleeps when it has nothing to do (as the desktop's
  // waits for an event): any input, a call below, or the time a timed job
  // asked for wakes it.
  let sleepTimer = null;
  function wake() {
    clearTimeout(sleepTimer);
    sleepTimer = null;
    if (isReady) Module.ccall('m3055_wake', null, [], []);
  }
  for (const type of ['keydown', 'keyup', 'mousedown', 'mouseup', 'mousemove', 'wheel', 'mouseover', 'mouseout',
                      'touchstart', 'touchmove', 'touchend', 'focus', 'blur', 'resize', 'drop'])
    window.addEventListener(type, wake, true);
  // An exported function of the explorer, then its loop woken to draw what it changed.
  function call(name, returns, types, args) {
    const result = Module.ccall(name, returns, types, args);
    wake();
    return result;
  }

  // Screenshots are numbered after every file downloaded before, in this
  // visit or an earlier one (the browser's downloads folder keeps them).
  const DOWNLOADS = 'm3055.downloads';
  const downloaded = new Set();
  try { for (const name of JSON.parse(localStorage.getItem(DOWNLOADS) || '[]')) downloaded.add(name); } catch (e) { /* none kept */ }
  function noteDownload(name) {
    downloaded.add(name);
    try { localStorage.setItem(DOWNLOADS, JSON.stringify(Array.from(downloaded).slice(-5000))); } catch (e) { /* not kept */ }
  }

  // Files written by the explorer (Save, Save as, F12) leave as downloads.
  function download(path) {
    const bytes = Module.FS.readFile(path);
    const type = path.endsWith('.png') ? 'image/png' : 'application/json';
    const url = URL.createObjectURL(new Blob([bytes], { type }));
    const a = document.createElement('a');
    a.href = url;
    a.download = basename(path);
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
    noteDownload(basename(path));
    say('downloaded ' + basename(path));
  }

  function writeWorkFile(name, data) {
    const path = WORK + '/' + name;
    const parts = path.split('/').slice(1, -1);
    let dir = '';
    for (const part of parts) {
      dir += '/' + part;
      try { Module.FS.mkdir(dir); } catch (e) { /* exists */ }
    }
    Module.FS.writeFile(path, data);
    return path;
  }

  // Picked files: every file into the work folder, then the scene (or the
  // one .brdf) opened, so a scene finds the .brdf and model files (.obj, .mtl,
  // .gltf, .glb, .bin) picked with it; a model file picked without a scene
  // (with its .mtl or .bin) is added to the scene, standing on the floor.
  async function openFiles(files) {
    const list = Array.from(files);
    if (list.some((f) => f.name === 'assignment.json')) return practiseFiles(list);
    for (const file of list) writeWorkFile(file.name, new Uint8Array(await file.arrayBuffer()));
    const isModel = (f) => /\.(obj|gltf|glb)$/i.test(f.name);
    const scene = list.find((f) => f.name.endsWith('.json')) || list.find(isModel) ||
                  list.find((f) => !/\.(brdf|mtl|bin)$/i.test(f.name)) || list[0];
    if (!scene) return;
    // A chooser gives names without folders: a .brdf or model file the scene
    // names in a subfolder ("brdfs/my.brdf", "meshes/vase.obj") and that was
    // picked with it ("my.brdf") is put where the scene looks for it too.
    if (!scene.name.endsWith('.brdf')) {
      let named = [];
      try {
        named = (JSON.parse(await scene.text()).objects || [])
          .flatMap((o) => [o && o.material && o.material.file, o && o.file]).filter((f) => typeof f === 'string');
      } catch (e) { /* not JSON: the loader says so */ }
      for (const name of named) {
        const picked = list.find((f) => f.name === basename(name));
        if (picked && name.includes('/') && !name.startsWith('/') && !name.split('/').includes('..'))
          writeWorkFile(name, new Uint8Array(await picked.arrayBuffer()));
      }
    }
    const error = call('m3055_open_file', 'string', ['string'], [scene.name]);
    say(error ? 'could not open ' + scene.name : 'opened ' + scene.name);  // the error: the error line
    canvas.focus();
  }
  // Picked files being read (m3055.settled() waits for them too), and how
  // many picks were handled (m3055.filesHandled(): a folder chooser's change
  // event comes a while after the pick, once the folder has been listed).
  let filesInFlight = 0, filesHandled = 0;
  function reading(work) {
    ++filesInFlight;
    work.finally(() => { --filesInFlight; ++filesHandled; });
  }
  fileInput.addEventListener('change', () => { reading(openFiles(fileInput.files)); fileInput.value = ''; });
  // Files dropped on the explorer go where picked files go (the work folder,
  // not GLFW's own folder), so a saved scene and a share link name and carry
  // them as picked ones: a scene, a .brdf, or a model file (with its .mtl or .bin).
  canvas.addEventListener('dragover', (e) => e.preventDefault());
  window.addEventListener('drop', (e) => {
    if (e.target !== canvas || !e.dataTransfer || !e.dataTransfer.files.length) return;
    e.preventDefault();
    e.stopPropagation();  // before GLFW's handler on the canvas
    reading(openFiles(e.dataTransfer.files));
  }, true);

  // Practice mode from the student's own copy of an assignment: its folder
  // (Practise…, a folder chooser) or its files (Open… with assignment.json
  // among them). The .json and .brdf files go into a fresh folder under the
  // work folder, in their places under the picked folder; the shallowest
  // assignment.json is graded with the same code as ?assignment=.
  let practiceUploads = 0;
  async function practiseFiles(files) {
    const list = Array.from(files).filter((f) => /\.(json|brdf)$/.test(f.name));
    const place = (f) => f.webkitRelativePath || f.name;
    const folder = 'practice-' + (++practiceUploads);
    for (const file of list) writeWorkFile(folder + '/' + place(file), new Uint8Array(await file.arrayBuffer()));
    const assignment = list.filter((f) => f.name === 'assignment.json')
      .sort((a, b) => place(a).split('/').length - place(b).split('/').length)[0];
    if (!assignment) {
      showError('practice: no assignment.json among the picked files: pick the assignment\'s folder');
      return;
    }
    const error = call('m3055_practise', 'string', ['string'], [WORK + '/' + folder + '/' + place(assignment)]);
    if (error) showError(error);
    say(error ? 'practice did not start' : 'practising ' + place(assignment) + ': graded as you edit; Ctrl+S downloads submission.json');
    canvas.focus();
  }
  const folderInput = document.getElementById('assignment-folder');
  folderInput.addEventListener('change', () => { reading(practiseFiles(folderInput.files)); folderInput.value = ''; });
  document.getElementById('practise').addEventListener('click', () => folderInput.click());
  document.getElementById('open').addEventListener('click', () => fileInput.click());

  async function shareLink() {
    await ready;
    const fragment = Module.ccall('m3055_share_fragment', 'string', [], []);
    if (!fragment) throw new Error(Module.ccall('m3055_last_error', 'string', [], []));
    return location.origin + location.pathname + location.search + '#' + fragment;
  }
  document.getElementById('share').addEventListener('click', async () => {
    let link;
    try {
      link = await shareLink();
    } catch (e) {
      showError(e.message);
      return;
    }
    try {
      await navigator.clipboard.writeText(link);
      say('share link copied (' + link.length + ' characters)');
    } catch (e) {
      window.prompt('Copy the share link:', link);
    }
  });

  // Browser shortcuts that would fight the explorer's: Ctrl+S saves the
  // scene, not the page; Ctrl+Z/Y, F1 and F12 are the explorer's; Ctrl+O is
  // Open… (a key press may open the file chooser, as a click on the bar may).
  // Ctrl+digit stays the browser's: the figure keys are Ctrl+Alt+digit.
  window.addEventListener('keydown', (e) => {
    const ctrl = e.ctrlKey || e.metaKey;
    const key = (e.key || '').toLowerCase();
    if ((ctrl && ['a', 's', 'o', 'z', 'y'].includes(key)) || e.key === 'F1' || e.key === 'F12') e.preventDefault();
    if (ctrl && !e.altKey && !e.shiftKey && key === 'o' && !e.repeat) fileInput.click();
    if (e.key === 'Escape' && !help.hidden) help.hidden = true;
  }, true);

  // The page's help: the keys (the figure keys the browser does not own).
  const help = document.getElementById('help');
  document.getElementById('help-button').addEventListener('click', () => { help.hidden = !help.hidden; });

  // Closing or reloading the tab with unsaved edits: the browser asks first,
  // as the desktop explorer does before it quits.
  window.addEventListener('beforeunload', (e) => {
    if (!isReady || !Module.ccall('m3055_unsaved', 'number', [], [])) return;
    e.preventDefault();
    e.returnValue = '';
  });

  // Practice mode: ?assignment=FOLDER/ fetches the assignment and its scenes
  // into the work folder; main() then starts with --assignment.
  async function fetchAssignment(url) {
    const base = new URL(url.endsWith('/') || url.endsWith('.json') ? url : url + '/', location.href);
    const jsonUrl = base.href.endsWith('.json') ? base : new URL('assignment.json', base);
    const response = await fetch(jsonUrl);
    if (!response.ok) throw new Error('assignment ' + jsonUrl + ': HTTP ' + response.status);
    const text = await response.text();
    const path = writeWorkFile('assignment/assignment.json', text);
    let spec = {};
    try { spec = JSON.parse(text); } catch (e) { return path; }  // the explorer names the error
    for (const key of ['reference', 'start']) {
      const name = spec[key];
      if (typeof name !== 'string' || name.includes('..') || name.startsWith('/')) continue;
      const r = await fetch(new URL(name, jsonUrl));
      if (r.ok) writeWorkFile('assignment/' + name, new Uint8Array(await r.arrayBuffer()));
    }
    return path;
  }

  async function start() {
    const args = [];
    const params = new URLSearchParams(location.search);
    try {
      if (params.get('assignment')) args.push('--assignment', await fetchAssignment(params.get('assignment')));
      if (params.get('script')) {  // UI actions, one a frame (explore/script.h): course pages, scripts/bench-web
        const response = await fetch(new URL(params.get('script'), location.href));
        if (!response.ok) throw new Error('script ' + params.get('script') + ': HTTP ' + response.status);
        args.push('--script', writeWorkFile('script.txt', await response.text()));
      }
      const hash = new URLSearchParams(location.hash.slice(1));
      if (hash.get('scene')) {
        writeWorkFile('.keep', '');
        const error = Module.ccall('m3055_unpack_share_token', 'string', ['string', 'string'],
                                   [hash.get('scene'), WORK + '/shared-scene.json']);
        if (error) startError = 'the share link did not open: ' + error;
        else args.push('shared-scene.json');  // relative to the work folder (main's): its .brdf files show by their names
      }
    } catch (e) {
      startError = String(e.message || e);
    }
    const [w, h] = deviceSize();
    canvas.width = w;
    canvas.height = h;
    Module.callMain(args);
  }

  // Input to pixels: from a pointer or key event on the canvas to the end of
  // the animation frame that rendered the changed scene (m3055.latency()).
  let pendingInput = null;
  const latencies = [];
  for (const type of ['mousemove', 'mousedown', 'keydown'])
    canvas.addEventListener(type, () => { if (pendingInput === null) pendingInput = performance.now(); }, true);

  window.m3055Page = {
    download,
    rendered: () => {
      if (pendingInput !== null) latencies.push(performance.now() - pendingInput);
      pendingInput = null;
    },
    // File > Open BRDF... and Ctrl+O: a browser opens its file chooser only
    // from a click on the page itself, which this is not (the explorer acts on
    // the click a frame later); the bar's Open... is.
    chooseFile: () => {
      say('use Open… in this bar: the browser opens its file chooser only from there');
      document.getElementById('open').focus();
    },
    started: () => {
      message.remove();
      say('ready: drop a scene, .brdf or model file on the explorer, or use Open…');
      if (startError) showError(startError);
      canvas.focus();
      started();
    },
    // The loop sleeps until the next input, or `ms` milliseconds (>= 0).
    sleeping: (ms) => {
      clearTimeout(sleepTimer);
      sleepTimer = ms >= 0 ? setTimeout(wake, ms) : null;
    },
    explorerError: (text) => {
      if (text) showError(text);
      else if (errorText.textContent === explorerError) showError('');
      explorerError = text;
    },
    downloadedBefore: (name) => downloaded.has(name),
    startFailed: () => {
      message.textContent = 'The explorer could not start: ' + (window.m3055Page.lastError || 'see the console');
      failed(new Error(message.textContent));
    },
  };

  // The canvas's drawing buffer follows its size in device pixels: a resized
  // window, the bar growing (an error line), the browser's zoom or another screen.
  function fitCanvas() {
    if (!Module.setCanvasSize) return;
    const [w, h] = deviceSize();
    if (w !== canvas.width || h !== canvas.height) Module.setCanvasSize(w, h);
    wake();
  }
  window.addEventListener('resize', fitCanvas);
  new ResizeObserver(fitCanvas).observe(canvas);
  (function watchPixelRatio() {
    matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`).addEventListener('change', () => { fitCanvas(); watchPixelRatio(); }, { once: true });
  })();

  window.Module = {
    canvas,
    print: (text) => console.log(text),
    printErr: (text) => { console.warn(text); window.m3055Page.lastError = text; },
    onRuntimeInitialized: start,
    onAbort: (what) => { message.textContent = 'The explorer stopped: ' + what; failed(new Error(String(what))); },
  };

  // The test API (docs/web.md): each call waits for the explorer to start.
  function rejectIf(error) { if (error) throw new Error(error); }
  window.m3055 = {
    ready,
    async loadScene(jsonText, name = 'scene.json') {
      await ready;
      writeWorkFile(name, jsonText);
      rejectIf(call('m3055_load_scene', 'string', ['string'], [name]));
    },
    async displayPNG() {
      await ready;
      const url = call('m3055_display_png', 'string', [], []);
      if (!url) throw new Error(Module.ccall('m3055_last_error', 'string', [], []));
      return url;
    },
    async addFile(name, text) {
      await ready;
      writeWorkFile(name, text);
    },
    async gradeLine() {
      await ready;
      return call('m3055_grade_line', 'string', [], []);
    },
    shareLink,
    // How many picks of files (Open…, Practise…) the page has handled so far.
    filesHandled: () => filesHandled,
    // Resolves once the explorer has handled every key and click sent so far
    // and every file picked in the page, and drawn what they changed (checked
    // each animation frame); rejects after timeoutMs. Input is fed one
    // transition per key a frame, so a typed word takes a few frames: wait
    // for this, not for a fixed time.
    async settled(timeoutMs = 30000) {
      await ready;
      const start = performance.now();
      while (filesInFlight > 0 || !Module.ccall('m3055_idle', 'number', [], [])) {
        if (performance.now() - start > timeoutMs) throw new Error(`the explorer was still busy after ${timeoutMs} ms`);
        await new Promise((resolve) => requestAnimationFrame(resolve));
      }
    },
    // The CPU time (ms) of each frame that rendered a changed scene so far.
    async frameTimes() {
      await ready;
      return JSON.parse(Module.ccall('m3055_render_frame_ms', 'string', [], []));
    },
    // Milliseconds from each input event (the first since the last render) to
    // the frame that rendered its change; clear: start a new measurement.
    latency(clear = false) {
      const samples = latencies.slice();
      if (clear) latencies.length = 0;
      return samples;
    },
  };
})();
