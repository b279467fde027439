// The Sound pass of the project page (docs/html-pages.md), as the site plays it: the
// pass draws 512x512 samples at a time into an RGBA8 target (its main() packs each
// channel into two bytes), the page reads them back and plays them through Web Audio.
// Embedded before runtime.js in the page's one script.
"use strict";
function spSound(gl) {
  const kRate = 44100;
  const kSide = 512;
  const kBlock = kSide * kSide;
  let tex = null;
  let fbo = null;
  let context = null;
  let source = null;

  function target() {
    if (fbo) return;
    tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, kSide, kSide);
    gl.bindTexture(gl.TEXTURE_2D, null);
    fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
  }

  // Samples [0, count) of `pass` (a linked Sound program); `prepare` sets its other
  // uniforms and textures. Returns {left, right} in [-1, 1].
  function synthesize(pass, count, prepare) {
    target();
    const left = new Float32Array(count);
    const right = new Float32Array(count);
    const px = new Uint8Array(kBlock * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.viewport(0, 0, kSide, kSide);
    gl.useProgram(pass.program);
    prepare();
    const offsetTime = gl.getUniformLocation(pass.program, "iTimeOffset");
    const offsetSample = gl.getUniformLocation(pass.program, "iSampleOffset");
    for (let offset = 0; offset < count; offset += kBlock) {
      if (offsetTime) gl.uniform1f(offsetTime, offset / kRate);
      if (offsetSample) gl.uniform1i(offsetSample, offset);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.readPixels(0, 0, kSide, kSide, gl.RGBA, gl.UNSIGNED_BYTE, px);
      const n = Math.min(kBlock, count - offset);
      for (let i = 0; i < n; ++i) {
        left[offset + i] = (px[4 * i] + 256 * px[4 * i + 1]) / 32768 - 1;
        right[offset + i] = (px[4 * i + 2] + 256 * px[4 * i + 3]) / 32768 - 1;
      }
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return {left: left, right: right};
  }

  // Plays `samples` from `seconds` on (wrapping), replacing what plays.
  function play(samples, seconds) {
    stop();
    if (!context) context = new AudioContext({sampleRate: kRate});
    const buffer = context.createBuffer(2, samples.left.length, kRate);
    buffer.copyToChannel(samples.left, 0);
    buffer.copyToChannel(samples.right, 1);
    source = context.createBufferSource();
    source.buffer = buffer;
    source.connect(context.destination);
    source.start(0, Math.max(0, seconds) % buffer.duration);
    context.resume();
  }

  function stop() {
    if (source) source.stop();
    source = null;
  }

  return {rate: kRate, synthesize: synthesize, play: play, stop: stop,
          playing: () => source !== null};
}
