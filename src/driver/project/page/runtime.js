// The project page's runtime (docs/html-pages.md): runs the ported passes of one
// ShaderToy project as shadertoy.com does. Embedded into the page by html_page.cpp;
// must never contain the text that ends a script element.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const stateEl = $("sp-state");
  const logEl = $("sp-log");
  const canvas = $("sp-canvas");

  // Problems go to the DOM as well as the console, so that a test reading the DOM
  // (chromium --dump-dom) sees them.
  function note(kind, text) {
    logEl.appendChild(document.createTextNode(kind + ": " + text + "\n"));
  }
  const consoleError = console.error.bind(console);
  console.error = function (...args) {
    note("console.error", args.map(String).join(" "));
    consoleError(...args);
  };
  window.addEventListener("error", (e) => note("exception", String(e.message)));
  window.addEventListener("unhandledrejection", (e) => note("rejection", String(e.reason)));
  function setState(state) { stateEl.setAttribute("data-state", state); }

  const project = JSON.parse($("sp-project").textContent);
  $("sp-title").textContent = project.name || "ShaderToy project";

  // #time=T&frames=N&size=WxH&frame=F&paused (the query string works too).
  const params = new URLSearchParams(location.search.slice(1));
  for (const [k, v] of new URLSearchParams(location.hash.slice(1))) params.set(k, v);
  const fixedTime = params.has("time") || params.has("frames");
  const startTime = params.has("time") ? Number(params.get("time")) : (fixedTime ? 1.0 : 0.0);
  const startFrame = params.has("frame") ? (Number(params.get("frame")) | 0) : 0;
  const frameLimit = params.has("frames") ? Math.max(1, Number(params.get("frames")) | 0) : 0;
  // mouse=x,y[,z,w]: iMouse as render's --mouse gives it, until the first click.
  let fixedMouse = null;
  if (params.has("mouse")) {
    fixedMouse = params.get("mouse").split(",").map(Number).slice(0, 4);
    while (fixedMouse.length < 4) fixedMouse.push(0);
    if (fixedMouse.some((v) => !isFinite(v))) fixedMouse = null;
  }
  let fixedSize = null;
  if (params.has("size")) {
    const m = /^(\d+)x(\d+)$/.exec(params.get("size"));
    if (m) fixedSize = [Math.max(1, Math.min(4096, +m[1])), Math.max(1, Math.min(4096, +m[2]))];
  }

  // A program of the user's own drawn on render's mesh needs a depth buffer.
  const gl = canvas.getContext("webgl2", {alpha: false, antialias: false,
    depth: project.passes.some((p) => p.mesh),
    stencil: false, premultipliedAlpha: false, preserveDrawingBuffer: true});
  if (!gl) {
    $("sp-fallback").hidden = false;
    canvas.hidden = true;
    note("error", "no WebGL2 context");
    setState("no-webgl2");
    return;
  }

  const gpu = spResources(gl, note);

  // --- Passes ----------------------------------------------------------------------------
  const kVertex = "#version 300 es\n" +
    "void main() {\n" +
    "  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);\n" +
    "  gl_Position = vec4(p, 0.0, 1.0);\n" +
    "}\n";
  const passes = project.passes.filter((p) => p.kind !== "common");
  const buffers = passes.filter((p) => p.kind === "buffer" && p.output >= 0 && p.output <= 3)
    .sort((a, b) => a.output - b.output);
  const cubePass = passes.find((p) => p.kind === "cube") || null;
  const imagePass = passes.find((p) => p.kind === "image") || null;
  const drawn = buffers.concat(cubePass ? [cubePass] : [], imagePass ? [imagePass] : []);
  const cubeSize = Math.max(1, Math.min(2048, project.cubeSize | 0 || 256));

  // Which buffers exist and which need mipmaps (an input reads them with "mipmap").
  const bufferUsed = [false, false, false, false];
  const bufferMips = [false, false, false, false];
  let cubeMips = false;
  for (const p of buffers) bufferUsed[p.output] = true;
  for (const p of drawn) {
    for (const input of p.inputs) {
      if (input.kind === "buffer" && input.buffer >= 0 && input.buffer <= 3) {
        bufferUsed[input.buffer] = true;
        if (input.filter === "mipmap") bufferMips[input.buffer] = true;
      }
      if (input.kind === "cubebuffer" && input.filter === "mipmap") cubeMips = true;
    }
  }

  // Maps a line of a pass's ported text to "Tab:line" in the user's code.
  function userLine(pass, line) {
    for (const [first, count, origin, userFirst] of pass.lines) {
      if (line >= first && line < first + count) return origin + ":" + (userFirst + line - first);
    }
    return pass.name + " (generated line " + line + ")";
  }
  const errorsEl = $("sp-errors");
  function showError(pass, where, lines, log) {
    errorsEl.hidden = false;
    const head = document.createElement("div");
    head.className = "sp-error-where";
    head.textContent = pass.name + ": " + where;
    const pre = document.createElement("pre");
    pre.textContent = lines.join("\n");
    errorsEl.appendChild(head);
    errorsEl.appendChild(pre);
    if (log) {
      const details = document.createElement("details");
      const summary = document.createElement("summary");
      summary.textContent = "the browser's log";
      const raw = document.createElement("pre");
      raw.textContent = log;
      details.appendChild(summary);
      details.appendChild(raw);
      errorsEl.appendChild(details);
    }
    note("compile-error", pass.name + ": " + lines.join(" | "));
  }
  // ANGLE's messages read "ERROR: 0:LINE: text"; each is put on the user's line.
  function mappedLog(pass, log) {
    const out = [];
    for (const line of log.split("\n")) {
      // A message without a line ("ERROR: -1:-1: ...", e.g. no main()) stays as it is.
      const m = /^(ERROR|WARNING): \d+:(\d+): (.*)$/.exec(line.trim());
      if (m) out.push(userLine(pass, +m[2]) + ": " + m[1].toLowerCase() + ": " + m[3]);
      else if (line.trim()) out.push(line.trim());
    }
    return out;
  }

  const vertexShader = gl.createShader(gl.VERTEX_SHADER);
  gl.shaderSource(vertexShader, kVertex);
  gl.compileShader(vertexShader);
  // The site's uniforms come from the harness model (spSiteUniforms, written before
  // this script); sound.js looks up mainSound's own.
  const kUniformNames = spSiteUniforms.concat(spEntryPointUniforms.mainCubemap);
  // What each site uniform is fed, by name (as render feeds it).
  const kFeeds = {
    iResolution: (l, v, w, h) => gl.uniform3f(l, w, h, 1),
    iTime: (l, v) => gl.uniform1f(l, v.time),
    iTimeDelta: (l, v) => gl.uniform1f(l, v.delta),
    iFrameRate: (l, v) => gl.uniform1f(l, v.fps),
    iFrame: (l, v) => gl.uniform1i(l, v.frame),
    iChannelTime: (l, v) => gl.uniform1fv(l, [v.time, v.time, v.time, v.time]),
    iChannelResolution: (l, v, w, h, res) => gl.uniform3fv(l, res),
    iMouse: (l, v) => gl.uniform4fv(l, v.mouse),
    iDate: (l, v) => gl.uniform4fv(l, v.date),
    iSampleRate: (l) => gl.uniform1f(l, 44100),
  };
  // Programs of the user's own (pass.vertex set) get render's inputs for the rest.
  const own = spOwnInputs(gl, gpu, kUniformNames);
  // A uniform the model lists that the page cannot feed stops the page, loudly.
  const unfed = spSiteUniforms.filter((name) => !kFeeds[name]);
  if (unfed.length) note("error", "the page cannot feed the uniforms " + unfed.join(", "));
  let failed = unfed.length > 0;
  for (const pass of passes) {
    if (pass.kind !== "image" && pass.kind !== "buffer" && pass.kind !== "cube" &&
        pass.kind !== "sound") continue;
    if (!pass.code) {
      failed = true;
      showError(pass, "the port failed", (pass.portErrors || "no shader text").split("\n"), "");
      continue;
    }
    const fs = gl.createShader(gl.FRAGMENT_SHADER);
    gl.shaderSource(fs, pass.code);
    gl.compileShader(fs);
    if (!gl.getShaderParameter(fs, gl.COMPILE_STATUS)) {
      failed = true;
      const log = gl.getShaderInfoLog(fs) || "";
      showError(pass, "does not compile", mappedLog(pass, log), log);
      continue;
    }
    let vs = vertexShader;
    if (pass.vertex) {
      vs = gl.createShader(gl.VERTEX_SHADER);
      gl.shaderSource(vs, pass.vertex);
      gl.compileShader(vs);
      if (!gl.getShaderParameter(vs, gl.COMPILE_STATUS)) {
        failed = true;
        const log = gl.getShaderInfoLog(vs) || "";
        showError(pass, "the vertex shader does not compile",
                  mappedLog({name: pass.name, lines: pass.vertexLines || []}, log), log);
        continue;
      }
    }
    const program = gl.createProgram();
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      failed = true;
      const log = gl.getProgramInfoLog(program) || "";
      showError(pass, "does not link", [log], "");
      continue;
    }
    pass.program = program;
    pass.loc = {};
    for (const name of kUniformNames) pass.loc[name] = gl.getUniformLocation(program, name);
    gl.useProgram(program);
    for (let c = 0; c < 4; ++c) {
      const loc = gl.getUniformLocation(program, "iChannel" + c);
      if (loc) gl.uniform1i(loc, c);
    }
    if (pass.vertex) {
      pass.own = own.uniforms(program);  // iChannelN too: render binds procedural ones
      if (pass.mesh) pass.meshVao = own.mesh(program);
    }
  }
  if (failed || !imagePass) {
    if (!imagePass) note("error", "the project has no Image pass");
    setState("error");
    $("sp-status").textContent = failed ? "compile errors" : "no Image pass";
    return;
  }

  // --- Buffers: ping-pong pairs, reallocated (cleared) on resize ------------------------
  let width = 0;
  let height = 0;
  const pairs = [null, null, null, null];
  const latest = [0, 0, 0, 0];
  let cubePair = null;
  let cubeLatest = 0;
  function allocate(w, h) {
    for (let k = 0; k < 4; ++k) {
      if (pairs[k]) { gpu.freeTarget(pairs[k][0]); gpu.freeTarget(pairs[k][1]); pairs[k] = null; }
      if (!bufferUsed[k]) continue;
      pairs[k] = [gpu.makeTarget(w, h, false, bufferMips[k]),
                  gpu.makeTarget(w, h, false, bufferMips[k])];
      latest[k] = 0;
    }
    if (cubePass && !cubePair) {
      cubePair = [gpu.makeTarget(cubeSize, cubeSize, true, cubeMips),
                  gpu.makeTarget(cubeSize, cubeSize, true, cubeMips)];
    }
    width = w;
    height = h;
  }
  function clearCube() {
    if (!cubePair) return;
    for (const t of cubePair) { gpu.freeTarget(t); }
    cubePair = null;
    cubeLatest = 0;
  }
  function resize() {
    let w, h;
    if (fixedSize) {
      [w, h] = fixedSize;
      canvas.classList.add("sp-fixed");
    } else {
      const dpr = window.devicePixelRatio || 1;
      w = Math.max(1, Math.round(canvas.clientWidth * dpr));
      h = Math.max(1, Math.round(canvas.clientHeight * dpr));
    }
    if (w === width && h === height) return false;
    canvas.width = w;
    canvas.height = h;
    allocate(w, h);
    return true;
  }

  // --- Inputs of one pass ------------------------------------------------------------------
  // The texture (and its size) channel `input` reads now; null: nothing bound.
  function sourceOf(input) {
    switch (input.kind) {
      case "buffer": {
        const pair = pairs[input.buffer];
        if (!pair) return null;
        return {tex: pair[latest[input.buffer]].tex, target: gl.TEXTURE_2D, size: [width, height, 1]};
      }
      case "cubebuffer":
        if (!cubePair) return null;
        return {tex: cubePair[cubeLatest].tex, target: gl.TEXTURE_CUBE_MAP,
                size: [cubeSize, cubeSize, 1]};
      case "keyboard": return gpu.keyboardTexture();
      case "texture": case "video": case "audio":
        return input.user || gpu.proceduralTexture("2d");
      case "cubemap": return gpu.proceduralTexture("cubemap");
      case "volume": return gpu.proceduralTexture("volume");
      default: return null;
    }
  }
  const kTargets = [gl.TEXTURE_2D, gl.TEXTURE_CUBE_MAP, gl.TEXTURE_3D];
  function bindInputs(pass) {
    const res = new Float32Array(12);
    for (let c = 0; c < 4; ++c) {
      gl.activeTexture(gl.TEXTURE0 + c);
      for (const t of kTargets) gl.bindTexture(t, null);
      gl.bindSampler(c, null);
      const input = pass.inputs.find((i) => i.channel === c);
      const source = input ? sourceOf(input) : null;
      if (!source) continue;
      gl.bindTexture(source.target, source.tex);
      // The keyboard texture has no mipmaps: a mipmap filter would leave it incomplete.
      const filter = input.kind === "keyboard" && input.filter === "mipmap" ? "linear" : input.filter;
      gl.bindSampler(c, gpu.samplerFor(filter, input.wrap));
      res.set(source.size, c * 3);
    }
    gl.activeTexture(gl.TEXTURE0);
    return res;
  }

  // --- Clock, mouse and date ---------------------------------------------------------------
  const f32 = Math.fround;
  let time = startTime;
  let frame = startFrame;
  let drawnFrames = 0;
  let delta = 1 / 60;
  let fps = 60;
  let paused = params.has("paused") && !frameLimit;
  const mouse = {x: 0, y: 0, ox: 0, oy: 0, down: false, click: false};
  function frameValues() {
    let t = time;
    let date = [2025, 0, 1, 43200];
    if (fixedTime) {
      // As render computes it, in float: time + (1/60) * frame index.
      t = f32(f32(startTime) + f32(f32(1 / 60) * (frame - startFrame)));
    } else {
      const d = new Date();
      date = [d.getFullYear(), d.getMonth(), d.getDate(),
              d.getHours() * 3600 + d.getMinutes() * 60 + d.getSeconds() + d.getMilliseconds() / 1000];
    }
    const m = fixedMouse ||
      [mouse.x, mouse.y, mouse.down ? mouse.ox : -mouse.ox, mouse.click ? mouse.oy : -mouse.oy];
    return {time: t, delta: fixedTime ? 1 / 60 : delta, fps: fixedTime ? 60 : fps, frame: frame,
            mouse: m, date: date};
  }
  function setUniforms(pass, v, w, h, res) {
    for (const name of spSiteUniforms) {
      if (pass.loc[name]) kFeeds[name](pass.loc[name], v, w, h, res);
    }
  }
  // The corners of cube face f as the site's cube main() mixes them (bottom-left,
  // bottom-right, top-right, top-left of the face in GL's cube-map layout), then the
  // eye at the origin.
  const kFaceCorners = [
    [[1, 1, 1], [1, 1, -1], [1, -1, -1], [1, -1, 1]],
    [[-1, 1, -1], [-1, 1, 1], [-1, -1, 1], [-1, -1, -1]],
    [[-1, 1, -1], [1, 1, -1], [1, 1, 1], [-1, 1, 1]],
    [[-1, -1, 1], [1, -1, 1], [1, -1, -1], [-1, -1, -1]],
    [[-1, 1, 1], [1, 1, 1], [1, -1, 1], [-1, -1, 1]],
    [[1, 1, -1], [-1, 1, -1], [-1, -1, -1], [1, -1, -1]],
  ];

  // --- One frame: Buffers A-D, Cube A, Image ---------------------------------------------
  const vao = gl.createVertexArray();
  function drawFrame() {
    const v = frameValues();
    gl.bindVertexArray(vao);
    gl.disable(gl.BLEND);
    gl.disable(gl.DEPTH_TEST);
    for (const pass of buffers) {
      const k = pass.output;
      const write = 1 - latest[k];
      const target = pairs[k][write];
      gl.bindFramebuffer(gl.FRAMEBUFFER, target.fbos[0]);
      gl.viewport(0, 0, width, height);
      gl.useProgram(pass.program);
      setUniforms(pass, v, width, height, bindInputs(pass));
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      latest[k] = write;
      if (target.mips) {
        gl.bindTexture(gl.TEXTURE_2D, target.tex);
        gl.generateMipmap(gl.TEXTURE_2D);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
    }
    if (cubePass) {
      const write = 1 - cubeLatest;
      const target = cubePair[write];
      gl.useProgram(cubePass.program);
      const res = bindInputs(cubePass);
      gl.viewport(0, 0, cubeSize, cubeSize);
      for (let f = 0; f < 6; ++f) {
        gl.bindFramebuffer(gl.FRAMEBUFFER, target.fbos[f]);
        setUniforms(cubePass, v, cubeSize, cubeSize, res);
        if (cubePass.loc.unViewport) gl.uniform4f(cubePass.loc.unViewport, 0, 0, cubeSize, cubeSize);
        if (cubePass.loc.unCorners) gl.uniform3fv(cubePass.loc.unCorners, kFaceCorners[f].flat().concat([0, 0, 0]));
        gl.drawArrays(gl.TRIANGLES, 0, 3);
      }
      cubeLatest = write;
      if (target.mips) {
        gl.bindTexture(gl.TEXTURE_CUBE_MAP, target.tex);
        gl.generateMipmap(gl.TEXTURE_CUBE_MAP);
        gl.bindTexture(gl.TEXTURE_CUBE_MAP, null);
      }
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, width, height);
    gl.useProgram(imagePass.program);
    setUniforms(imagePass, v, width, height, bindInputs(imagePass));
    if (imagePass.own) {
      // As render: cleared to transparent black, what the program does not draw stays so.
      own.set(imagePass.own, v.time, width, height);
      gl.clearColor(0, 0, 0, 0);
      gl.clear(gl.COLOR_BUFFER_BIT | (imagePass.mesh ? gl.DEPTH_BUFFER_BIT : 0));
    }
    if (imagePass.meshVao) {
      gl.bindVertexArray(imagePass.meshVao.vao);
      gl.enable(gl.DEPTH_TEST);
      gl.depthFunc(gl.LESS);
      gl.drawElements(gl.TRIANGLES, imagePass.meshVao.count, gl.UNSIGNED_INT, 0);
      gl.disable(gl.DEPTH_TEST);
      gl.bindVertexArray(vao);
    } else {
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    // Keypresses and the click flag last one frame, as on the site.
    gpu.endFrame();
    mouse.click = false;
    frame += 1;
    drawnFrames += 1;
  }
  const reportedErrors = new Set();
  function checkGlErrors() {
    for (let e = gl.getError(); e !== gl.NO_ERROR; e = gl.getError()) {
      if (e === gl.CONTEXT_LOST_WEBGL) break;
      if (!reportedErrors.has(e)) note("gl-error", "0x" + e.toString(16) + " by frame " + frame);
      reportedErrors.add(e);
    }
  }

  // The last frame's pixels, top row first, as base64 RGBA8 (for tests).
  function publishPixels() {
    const px = new Uint8Array(width * height * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const rows = new Uint8Array(px.length);
    const stride = width * 4;
    for (let y = 0; y < height; ++y) rows.set(px.subarray((height - 1 - y) * stride, (height - y) * stride), y * stride);
    let s = "";
    for (let i = 0; i < rows.length; i += 0x8000) s += String.fromCharCode.apply(null, rows.subarray(i, i + 0x8000));
    const out = $("sp-pixels");
    out.setAttribute("data-width", String(width));
    out.setAttribute("data-height", String(height));
    out.textContent = btoa(s);
  }

  // --- Sound: the whole track is drawn once (kSoundSeconds) and played from iTime ---------
  const kSoundSeconds = 60;
  const soundPass = passes.find((p) => p.kind === "sound" && p.program) || null;
  const audio = spSound(gl);
  let soundWanted = false;
  let track = null;
  function soundSamples(count) {
    const n = count || kSoundSeconds * audio.rate;
    if (track && track.left.length >= n) return track;
    const samples = audio.synthesize(soundPass, n,
      () => setUniforms(soundPass, frameValues(), 512, 512, bindInputs(soundPass)));
    if (!count) track = samples;
    return samples;
  }
  // Plays while wanted and not paused, from the current iTime.
  function syncSound() {
    if (!soundPass) return;
    const play = soundWanted && !paused;
    if (play && !audio.playing()) audio.play(soundSamples(), frameValues().time);
    if (!play && audio.playing()) audio.stop();
    if (soundButton) soundButton.textContent = soundWanted ? "Sound off" : "Sound on";
  }
  let soundButton = null;
  if (soundPass) {
    // Browsers start audio only after a click, so sound waits for this button.
    soundButton = document.createElement("button");
    soundButton.type = "button";
    soundButton.id = "sp-sound-toggle";
    soundButton.addEventListener("click", () => {
      soundWanted = !soundWanted;
      syncSound();
    });
    $("sp-controls").insertBefore(soundButton, $("sp-clock"));
  }

  // sound=N: the first N samples of the Sound pass, every 100th as [left, right] (tests).
  function publishSound(count) {
    const samples = soundSamples(Math.max(1, Math.min(count, 4 * 512 * 512)));
    const out = [];
    for (let i = 0; i < samples.left.length; i += 100) {
      out.push([+samples.left[i].toFixed(5), +samples.right[i].toFixed(5)]);
    }
    const pre = document.createElement("pre");
    pre.id = "sp-sound";
    pre.hidden = true;
    pre.textContent = JSON.stringify(out);
    document.body.appendChild(pre);
  }

  // --- Controls ------------------------------------------------------------------------------
  const pauseButton = $("sp-pause");
  // While paused, a click still draws a frame (as on the site) so iMouse shows.
  let forced = false;
  function forceFrame() { if (paused) forced = true; }
  function setPaused(p) {
    paused = p;
    pauseButton.textContent = paused ? "Resume" : "Pause";
    syncSound();
  }
  function restart() {
    time = fixedTime ? startTime : 0;
    frame = startFrame;
    width = height = 0;
    clearCube();
    resize();
    if (paused) drawFrame();
    if (audio.playing()) audio.play(soundSamples(), 0);
  }
  pauseButton.addEventListener("click", () => setPaused(!paused));
  $("sp-restart").addEventListener("click", restart);
  setPaused(paused);
  // Keys go to the shader while the canvas has focus (click it); elsewhere space pauses.
  document.addEventListener("keydown", (e) => {
    if (document.activeElement !== canvas) {
      if (e.code === "Space" && !(e.target instanceof HTMLButtonElement)) {
        e.preventDefault();
        setPaused(!paused);
      }
      return;
    }
    const k = e.keyCode & 255;
    e.preventDefault();
    if (e.repeat) return;
    gpu.keyDown(k);
  });
  document.addEventListener("keyup", (e) => {
    if (document.activeElement !== canvas) return;
    gpu.keyUp(e.keyCode & 255);
  });
  canvas.addEventListener("blur", () => gpu.allKeysUp());
  // iMouse: xy while the button is down, zw the click; z < 0 after release, w > 0
  // only on the click's frame.
  function canvasPoint(e) {
    const r = canvas.getBoundingClientRect();
    return [Math.floor((e.clientX - r.left) * canvas.width / Math.max(1, r.width)),
            Math.floor(canvas.height - (e.clientY - r.top) * canvas.height / Math.max(1, r.height))];
  }
  canvas.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    canvas.focus();
    canvas.setPointerCapture(e.pointerId);
    [mouse.x, mouse.y] = canvasPoint(e);
    mouse.ox = mouse.x;
    mouse.oy = mouse.y;
    mouse.down = true;
    mouse.click = true;
    fixedMouse = null;
    forceFrame();
  });
  canvas.addEventListener("pointermove", (e) => {
    if (mouse.down) [mouse.x, mouse.y] = canvasPoint(e);
  });
  const release = () => {
    mouse.down = false;
    forceFrame();
  };
  canvas.addEventListener("pointerup", release);
  canvas.addEventListener("pointercancel", release);

  // A 2D channel's texture can be replaced by an image file (kept on this page only).
  const channelsEl = $("sp-channels");
  for (const pass of drawn) {
    for (const input of pass.inputs) {
      if (input.kind !== "texture") continue;
      const label = document.createElement("label");
      label.textContent = pass.name + " iChannel" + input.channel + ": ";
      const file = document.createElement("input");
      file.type = "file";
      file.accept = "image/*";
      file.addEventListener("change", () => {
        if (!file.files || !file.files[0]) return;
        const url = URL.createObjectURL(file.files[0]);
        const img = new Image();
        img.onload = () => {
          const tex = gl.createTexture();
          gl.bindTexture(gl.TEXTURE_2D, tex);
          gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, input.vflip);
          gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, img);
          gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
          gl.generateMipmap(gl.TEXTURE_2D);
          if (input.user) gl.deleteTexture(input.user.tex);
          input.user = {tex: tex, target: gl.TEXTURE_2D, size: [img.width, img.height, 1]};
          URL.revokeObjectURL(url);
        };
        img.onerror = () => note("warning", "the image could not be read");
        img.src = url;
      });
      label.appendChild(file);
      channelsEl.appendChild(label);
    }
  }

  let lost = false;
  canvas.addEventListener("webglcontextlost", (e) => {
    e.preventDefault();
    lost = true;
    note("error", "the WebGL context was lost");
    setState("context-lost");
    $("sp-status").textContent = "WebGL context lost";
  });

  // --- Run ---------------------------------------------------------------------------------
  resize();
  $("sp-status").textContent = "WebGL2, buffers " + gpu.format().name;
  const clockEl = $("sp-clock");
  function showClock() {
    clockEl.textContent = "iTime " + frameValues().time.toFixed(2) + "  iFrame " + frame +
      "  " + fps.toFixed(0) + " fps";
  }
  if (frameLimit) {
    // Deterministic: exactly N frames, drawn now, then the picture is published.
    for (let i = 0; i < frameLimit && !lost; ++i) {
      drawFrame();
      checkGlErrors();
    }
    if (!lost) {
      publishPixels();
      if (soundPass && params.has("sound")) publishSound(Number(params.get("sound")) | 0);
      checkGlErrors();
      showClock();
      setState("done");
    }
    stateEl.setAttribute("data-frames", String(drawnFrames));
    return;
  }
  let last = performance.now();
  function tick(now) {
    if (lost) return;
    const dt = Math.max(0, (now - last) / 1000);
    last = now;
    if ((resize() || forced) && paused) drawFrame();
    forced = false;
    if (!paused) {
      // The first frame after a (re)start is drawn at the start time.
      if (!fixedTime && frame !== startFrame) {
        delta = dt;
        if (dt > 0) fps = fps * 0.9 + 0.1 / dt;
        time += dt;
      }
      drawFrame();
      if (drawnFrames % 60 === 1) checkGlErrors();
    }
    showClock();
    setState(paused ? "paused" : "running");
    stateEl.setAttribute("data-frames", String(drawnFrames));
    requestAnimationFrame(tick);
  }
  setState("running");
  requestAnimationFrame(tick);
})();
