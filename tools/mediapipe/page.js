// Runs inside headless chromium: MediaPipe Pose on one image at a time, loaded from the local
// server that detect.js started; detect.js says when a camera's sequence starts and in which mode.
'use strict';

const simcapPose = new Pose({locateFile: (file) => '/mediapipe/' + file});
let simcapLast = null;
simcapPose.onResults((results) => {
  simcapLast = results.poseLandmarks
    ? results.poseLandmarks.map((l) => [l.x, l.y, l.visibility === undefined ? 0 : l.visibility])
    : null;
});

window.simcapInit = async (options) => {
  simcapPose.setOptions({
    modelComplexity: options.modelComplexity,
    minDetectionConfidence: options.minDetectionConfidence,
    smoothLandmarks: false,
    enableSegmentation: false,
    selfieMode: false,
  });
  await simcapPose.initialize();
};

// An all-black frame: the landmark model finds no pose in it, so the region MediaPipe tracks
// from the previous frame is dropped and the next image starts with the person detector, as
// after reset() but without rebuilding the graph (reset() costs seconds on SwiftShader).
async function simcapForget(width, height, at) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const context = canvas.getContext('2d');
  context.fillStyle = '#000';
  context.fillRect(0, 0, width, height);
  await simcapPose.send({image: canvas}, at);
}

// mode 'restart': reset() (a new camera's sequence); 'forget': drop the tracked region first
// (every image on its own); 'track': go on from the previous image of the same camera.
// at: the image's timestamp in ms. MediaPipe smooths the landmarks it derives the next region
// from over time, so a timestamp from the clock (send's default) would make results vary.
window.simcapDetect = async (url, mode, at) => {
  const image = new Image();
  image.src = url;
  await image.decode();
  if (mode === 'restart') {
    simcapPose.reset();
  } else if (mode === 'forget') {
    await simcapForget(image.naturalWidth, image.naturalHeight, at - 1);
  }
  simcapLast = null;
  await simcapPose.send({image}, at);
  return {width: image.naturalWidth, height: image.naturalHeight, landmarks: simcapLast};
};
