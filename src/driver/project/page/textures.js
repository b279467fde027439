// GPU resources of the project page (docs/html-pages.md): render targets with
// their format fallbacks, render's procedural textures, the keyboard texture and
// sampler objects. Embedded before runtime.js in the page's one script.
"use strict";
function spResources(gl, note) {
  // --- Render targets: RGBA32F as the site, 16F when 32F cannot be filtered --------------
  const hasFloat = !!gl.getExtension("EXT_color_buffer_float");
  const hasFloatLinear = !!gl.getExtension("OES_texture_float_linear");
  const hasHalf = hasFloat || !!gl.getExtension("EXT_color_buffer_half_float");
  const formats = [];
  if (hasFloat && hasFloatLinear) formats.push({internal: gl.RGBA32F, name: "RGBA32F"});
  if (hasHalf) formats.push({internal: gl.RGBA16F, name: "RGBA16F"});
  formats.push({internal: gl.RGBA8, name: "RGBA8"});
  let format = formats[0];

  function levelsFor(w, h, mips) {
    return mips ? Math.floor(Math.log2(Math.max(w, h))) + 1 : 1;
  }
  function attachTarget(target, face, tex) {
    const fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, face, tex, 0);
    const ok = gl.checkFramebufferStatus(gl.FRAMEBUFFER) === gl.FRAMEBUFFER_COMPLETE;
    gl.clearColor(0, 0, 0, 0);  // the site starts buffers at zero
    gl.clear(gl.COLOR_BUFFER_BIT);
    return ok ? fbo : null;
  }
  // A 2D target (faces 0) or a cube target (faces 6) with a framebuffer per face.
  function makeTarget(w, h, cube, mips) {
    const target = cube ? gl.TEXTURE_CUBE_MAP : gl.TEXTURE_2D;
    const tex = gl.createTexture();
    gl.bindTexture(target, tex);
    gl.texStorage2D(target, levelsFor(w, h, mips), format.internal, w, h);
    gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.bindTexture(target, null);
    const fbos = [];
    for (let f = 0; f < (cube ? 6 : 1); ++f) {
      const fbo = attachTarget(target, cube ? gl.TEXTURE_CUBE_MAP_POSITIVE_X + f : gl.TEXTURE_2D, tex);
      if (!fbo) return null;
      fbos.push(fbo);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return {tex: tex, fbos: fbos, target: target, w: w, h: h, mips: mips};
  }
  function freeTarget(t) {
    if (!t) return;
    for (const fbo of t.fbos) gl.deleteFramebuffer(fbo);
    gl.deleteTexture(t.tex);
  }
  // Falls back to the next format when a framebuffer is incomplete.
  function makeTargetWithFallback(w, h, cube, mips) {
    for (;;) {
      const t = makeTarget(w, h, cube, mips);
      if (t) return t;
      const next = formats.indexOf(format) + 1;
      if (next >= formats.length) throw new Error("no colour-renderable buffer format");
      note("warning", format.name + " targets are incomplete; using " + formats[next].name);
      format = formats[next];
    }
  }

  // --- Procedural textures: byte for byte src/render/procedural_textures.cpp -----------
  function hash(x, y, z) {
    let h = Math.imul(x, 0x8da6b343) ^ Math.imul(y, 0xd8163841) ^ Math.imul(z, 0xcb1ab31f);
    h ^= h >>> 13;
    h = Math.imul(h, 0x5bd1e995);
    h ^= h >>> 15;
    return h >>> 0;
  }
  function procedural2D(size) {
    const t = new Uint8Array(size * size * 4);
    for (let y = 0; y < size; ++y) {
      for (let x = 0; x < size; ++x) {
        const i = (y * size + x) * 4;
        const check = ((Math.floor(x / 32) + Math.floor(y / 32)) % 2) === 0;
        t[i] = Math.floor(x * 255 / (size - 1)) & 255;
        t[i + 1] = Math.floor(y * 255 / (size - 1)) & 255;
        t[i + 2] = check ? 200 : 56;
        t[i + 3] = hash(x, y, 0) & 255;
      }
    }
    return t;
  }
  const kTint = [[230, 80, 80], [80, 200, 200], [110, 200, 90], [180, 90, 190], [90, 110, 230],
                 [220, 200, 80]];
  function proceduralCubeFace(face, size) {
    const t = new Uint8Array(size * size * 4);
    for (let y = 0; y < size; ++y) {
      for (let x = 0; x < size; ++x) {
        const i = (y * size + x) * 4;
        const shade = 160 + Math.floor((x + y) * 95 / (2 * (size - 1)));
        for (let c = 0; c < 3; ++c) t[i + c] = Math.floor(kTint[face % 6][c] * shade / 255) & 255;
        t[i + 3] = 255;
      }
    }
    return t;
  }
  function procedural3D(size) {
    const t = new Uint8Array(size * size * size * 4);
    for (let z = 0; z < size; ++z) {
      for (let y = 0; y < size; ++y) {
        for (let x = 0; x < size; ++x) {
          const h = hash(x, y, z + 1);
          const i = ((z * size + y) * size + x) * 4;
          t[i] = h & 255;
          t[i + 1] = (h >>> 8) & 255;
          t[i + 2] = (h >>> 16) & 255;
          t[i + 3] = (h >>> 24) & 255;
        }
      }
    }
    return t;
  }
  // Created on first use and shared by every channel of their kind; mipmapped as
  // render makes them (src/render/channel_textures.cpp). Rows are in GL order.
  const procedural = {};
  function proceduralTexture(kind) {
    if (procedural[kind]) return procedural[kind];
    const tex = gl.createTexture();
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
    let entry;
    if (kind === "cubemap") {
      gl.bindTexture(gl.TEXTURE_CUBE_MAP, tex);
      for (let f = 0; f < 6; ++f) {
        gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, gl.RGBA8, 64, 64, 0, gl.RGBA,
                      gl.UNSIGNED_BYTE, proceduralCubeFace(f, 64));
      }
      gl.generateMipmap(gl.TEXTURE_CUBE_MAP);
      entry = {tex: tex, target: gl.TEXTURE_CUBE_MAP, size: [64, 64, 1]};
    } else if (kind === "volume") {
      gl.bindTexture(gl.TEXTURE_3D, tex);
      gl.texImage3D(gl.TEXTURE_3D, 0, gl.RGBA8, 32, 32, 32, 0, gl.RGBA, gl.UNSIGNED_BYTE,
                    procedural3D(32));
      gl.generateMipmap(gl.TEXTURE_3D);
      entry = {tex: tex, target: gl.TEXTURE_3D, size: [32, 32, 32]};
    } else {
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 256, 0, gl.RGBA, gl.UNSIGNED_BYTE,
                    procedural2D(256));
      gl.generateMipmap(gl.TEXTURE_2D);
      entry = {tex: tex, target: gl.TEXTURE_2D, size: [256, 256, 1]};
    }
    procedural[kind] = entry;
    return entry;
  }

  // --- Keyboard: 256x3 R8, row 0 down, row 1 pressed this frame, row 2 toggled --------
  const keys = new Uint8Array(256 * 3);
  let keysDirty = false;
  let keyboard = null;
  function keyboardTexture() {
    if (!keyboard) {
      const tex = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R8, 256, 3, 0, gl.RED, gl.UNSIGNED_BYTE, keys);
      keyboard = {tex: tex, target: gl.TEXTURE_2D, size: [256, 3, 1]};
    }
    if (keysDirty) {
      gl.bindTexture(gl.TEXTURE_2D, keyboard.tex);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, 256, 3, gl.RED, gl.UNSIGNED_BYTE, keys);
      keysDirty = false;
    }
    return keyboard;
  }

  // --- Sampler objects, one per (filter, wrap) ------------------------------------------
  const samplers = {};
  function samplerFor(filter, wrap) {
    const key = filter + "/" + wrap;
    if (samplers[key]) return samplers[key];
    const s = gl.createSampler();
    const min = filter === "nearest" ? gl.NEAREST
      : filter === "linear" ? gl.LINEAR : gl.LINEAR_MIPMAP_LINEAR;
    gl.samplerParameteri(s, gl.TEXTURE_MIN_FILTER, min);
    gl.samplerParameteri(s, gl.TEXTURE_MAG_FILTER, filter === "nearest" ? gl.NEAREST : gl.LINEAR);
    const w = wrap === "clamp" ? gl.CLAMP_TO_EDGE : gl.REPEAT;
    gl.samplerParameteri(s, gl.TEXTURE_WRAP_S, w);
    gl.samplerParameteri(s, gl.TEXTURE_WRAP_T, w);
    gl.samplerParameteri(s, gl.TEXTURE_WRAP_R, w);
    samplers[key] = s;
    return s;
  }

  return {
    format: () => format,
    makeTarget: makeTargetWithFallback,
    freeTarget: freeTarget,
    proceduralTexture: proceduralTexture,
    keyboardTexture: keyboardTexture,
    samplerFor: samplerFor,
    // Keyboard state: down, pressed this frame, toggled (by keyCode).
    keyDown: (k) => { keys[k] = 255; keys[256 + k] = 255; keys[512 + k] ^= 255; keysDirty = true; },
    keyUp: (k) => { keys[k] = 0; keysDirty = true; },
    allKeysUp: () => { keys.fill(0, 0, 512); keysDirty = true; },
    endFrame: () => {
      if (keys.subarray(256, 512).some((b) => b !== 0)) { keys.fill(0, 256, 512); keysDirty = true; }
    },
  };
}

// A program of the user's own (not a ShaderToy tab) gets what `shaderport render`
// feeds it (src/render/uniform_values.cpp, render_mesh.cpp): uniforms by name and
// type, procedural textures for its samplers, and the unit sphere (32 x 16) with
// each attribute fed the stream its name suggests.
function spOwnInputs(gl, gpu, skip) {
  const f32 = Math.fround;
  function perspective(aspect) {
    const f = f32(1 / Math.tan(f32(60 * f32(3.14159265) / 180) / 2));
    const m = new Float32Array(16);
    m[0] = f / aspect; m[5] = f; m[10] = (100 + 0.1) / (0.1 - 100); m[11] = -1;
    m[14] = 2 * 100 * 0.1 / (0.1 - 100);
    return m;
  }
  function identity(n) {
    const m = new Float32Array(n * n);
    for (let i = 0; i < n; ++i) m[i * n + i] = 1;
    return m;
  }
  const kFloats = {[gl.FLOAT]: 1, [gl.FLOAT_VEC2]: 2, [gl.FLOAT_VEC3]: 3, [gl.FLOAT_VEC4]: 4};
  const kInts = {[gl.INT]: 1, [gl.INT_VEC2]: 2, [gl.INT_VEC3]: 3, [gl.INT_VEC4]: 4,
    [gl.BOOL]: 1, [gl.BOOL_VEC2]: 2, [gl.BOOL_VEC3]: 3, [gl.BOOL_VEC4]: 4};
  const kUints = {[gl.UNSIGNED_INT]: 1, [gl.UNSIGNED_INT_VEC2]: 2, [gl.UNSIGNED_INT_VEC3]: 3,
    [gl.UNSIGNED_INT_VEC4]: 4};
  const kMatrices = {[gl.FLOAT_MAT2]: 2, [gl.FLOAT_MAT3]: 3, [gl.FLOAT_MAT4]: 4};
  const kSamplers = {[gl.SAMPLER_2D]: "2d", [gl.SAMPLER_CUBE]: "cubemap", [gl.SAMPLER_3D]: "volume"};

  // The active uniforms `skip` does not set (ShaderToy's), samplers on units 4 and up.
  function uniforms(program) {
    const out = [];
    let unit = 4;
    const n = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
    gl.useProgram(program);
    for (let i = 0; i < n; ++i) {
      const info = gl.getActiveUniform(program, i);
      const loc = gl.getUniformLocation(program, info.name);
      let name = info.name;
      if (!loc) continue;  // a uniform block member
      if (name.length > 3 && name.endsWith("[0]")) name = name.slice(0, -3);
      if (skip.includes(name)) continue;
      const u = {loc: loc, type: info.type, size: info.size, lower: name.toLowerCase(), unit: -1};
      if (info.type in kSamplers) {
        u.unit = unit++;
        gl.uniform1i(loc, u.unit);
      }
      out.push(u);
    }
    return out;
  }

  function set(list, time, w, h) {
    for (const u of list) {
      if (u.unit >= 0) {
        gl.activeTexture(gl.TEXTURE0 + u.unit);
        const t = gpu.proceduralTexture(kSamplers[u.type]);
        gl.bindTexture(t.target, t.tex);
        gl.bindSampler(u.unit, gpu.samplerFor("mipmap", "repeat"));
        gl.activeTexture(gl.TEXTURE0);
      } else if (u.type in kFloats) {
        const k = kFloats[u.type];
        let v = [0.5, 0.5, 0.5, 1];
        if (u.lower.includes("texel")) v = [1 / w, 1 / h, 0, 0];
        else if (/resolution|viewport|size/.test(u.lower)) v = [w, h, 1, 1];
        else if (u.lower.includes("time")) v = [time, time, time, time];
        const data = [];
        for (let i = 0; i < u.size; ++i) data.push(...v.slice(0, k));
        gl["uniform" + k + "fv"](u.loc, data);
      } else if (u.type in kMatrices) {
        const n = kMatrices[u.type];
        let m = identity(n);
        if (n === 4 && u.lower.includes("proj")) m = perspective(f32(w / h));
        else if (n === 4 && u.lower.includes("view")) m[14] = -3;  // camera 3 units back
        const data = [];
        for (let i = 0; i < u.size; ++i) data.push(...m);
        gl["uniformMatrix" + n + "fv"](u.loc, false, data);
      } else if (u.type in kInts) {
        gl["uniform" + kInts[u.type] + "iv"](u.loc, new Array(u.size * kInts[u.type]).fill(1));
      } else if (u.type in kUints) {
        gl["uniform" + kUints[u.type] + "uiv"](u.loc, new Array(u.size * kUints[u.type]).fill(1));
      }
    }
  }

  function stream(name) {
    const lower = name.toLowerCase().split("vertex").join("");  // "vertexColor" is a colour
    if (lower.includes("norm")) return "normals";
    if (lower.includes("tangent")) return "tangents";
    if (/uv|tex|coord/.test(lower)) return "texCoords";
    if (lower.includes("col")) return "colors";
    return "positions";
  }
  function sphere(slices, stacks) {
    const m = {positions: [], normals: [], texCoords: [], colors: [], tangents: [], indices: []};
    const pi = f32(3.14159265);
    for (let j = 0; j <= stacks; ++j) {
      const v = f32(j / stacks);
      const theta = f32(v * pi);
      for (let i = 0; i <= slices; ++i) {
        const u = f32(i / slices);
        const phi = f32(f32(u * 2) * pi);
        const x = f32(Math.sin(theta) * Math.cos(phi));
        const y = f32(Math.cos(theta));
        const z = f32(Math.sin(theta) * Math.sin(phi));
        m.positions.push(x, y, z, 1);
        m.normals.push(x, y, z, 0);
        m.texCoords.push(u, 1 - v, 0, 1);
        m.colors.push(x * 0.5 + 0.5, y * 0.5 + 0.5, z * 0.5 + 0.5, 1);
        m.tangents.push(-Math.sin(phi), 0, Math.cos(phi), 1);
      }
    }
    const row = slices + 1;
    for (let j = 0; j < stacks; ++j) {
      for (let i = 0; i < slices; ++i) {
        const a = j * row + i;
        const b = a + row;
        m.indices.push(a, b, a + 1, a + 1, b, b + 1);
      }
    }
    return m;
  }
  const kComponents = {[gl.FLOAT]: 1, [gl.FLOAT_VEC2]: 2, [gl.FLOAT_VEC3]: 3, [gl.FLOAT_VEC4]: 4};
  // A vertex array with the program's active attributes fed from the sphere.
  function mesh(program) {
    const m = sphere(32, 16);
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const n = gl.getProgramParameter(program, gl.ACTIVE_ATTRIBUTES);
    for (let i = 0; i < n; ++i) {
      const info = gl.getActiveAttrib(program, i);
      const loc = gl.getAttribLocation(program, info.name);
      const k = kComponents[info.type];
      if (loc < 0 || !k) continue;  // gl_VertexID and friends, int attributes
      const buffer = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(m[stream(info.name)]), gl.STATIC_DRAW);
      gl.vertexAttribPointer(loc, k, gl.FLOAT, false, 16, 0);
      gl.enableVertexAttribArray(loc);
    }
    const indices = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indices);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint32Array(m.indices), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    return {vao: vao, count: m.indices.length};
  }
  return {uniforms: uniforms, set: set, mesh: mesh};
}
