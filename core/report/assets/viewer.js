// The report's 3D view (three.js): the map as points coloured by height,
// intensity or error, the trajectories and loop closures as lines, orbit /
// pan / zoom, top and side views at equal scale, the nearest trajectory
// sample under the mouse. Renders on demand (after each change).
/* global THREE */
(function () {
  'use strict';

  // Colour ramp (viridis, 6 stops) for heights and intensities; errors go green -> yellow -> red.
  const RAMPS = {
    viridis: [[0.267, 0.005, 0.329], [0.254, 0.265, 0.530], [0.164, 0.471, 0.558],
              [0.135, 0.659, 0.518], [0.478, 0.821, 0.318], [0.993, 0.906, 0.144]],
    error: [[0.10, 0.60, 0.25], [0.95, 0.85, 0.20], [0.85, 0.15, 0.10]],
  };

  function rampColor(ramp, u, out, offset) {
    const stops = RAMPS[ramp];
    const x = Math.min(1, Math.max(0, u)) * (stops.length - 1);
    const i = Math.min(stops.length - 2, Math.floor(x));
    const f = x - i;
    for (let c = 0; c < 3; ++c) out[offset + c] = stops[i][c] * (1 - f) + stops[i + 1][c] * f;
  }

  // The p-th and (100-p)-th percentiles of values (a colour range robust to outliers).
  function robustRange(values, p) {
    const sorted = Float32Array.from(values).sort();
    if (sorted.length === 0) return [0, 1];
    const lo = sorted[Math.floor((sorted.length - 1) * p / 100)];
    const hi = sorted[Math.ceil((sorted.length - 1) * (100 - p) / 100)];
    return hi > lo ? [lo, hi] : [lo - 0.5, lo + 0.5];
  }

  function Viewer(container, layers) {
    this.container = container;
    this.layers = {};
    this.trajectories = layers.trajectories;
    this.renderer = new THREE.WebGLRenderer({antialias: true});
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0x11151c);
    this.renderer.localClippingEnabled = true;  // the map's height cut (setHeightCut)
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.bounds = new THREE.Box3();
    if (layers.map) this.addMap(layers.map);
    for (const t of layers.trajectories) this.addTrajectory(t);
    if (layers.loops) this.addLoops(layers.loops);
    if (this.bounds.isEmpty()) this.bounds.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
    this.addGrid();
    this.resize();
    this.setView('3d');
    window.addEventListener('resize', () => { this.resize(); this.render(); });
  }

  Viewer.prototype.addMap = function (map) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(map.xyz, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(map.xyz.length), 3));
    const material = new THREE.PointsMaterial({size: 2, sizeAttenuation: false, vertexColors: THREE.VertexColors});
    this.heightCut = new THREE.Plane(new THREE.Vector3(0, 0, -1), Infinity);
    material.clippingPlanes = [this.heightCut];
    const points = new THREE.Points(geometry, material);
    this.scene.add(points);
    this.layers.map = points;
    this.mapData = map;
    geometry.computeBoundingBox();
    this.bounds.union(geometry.boundingBox);
  };

  Viewer.prototype.addTrajectory = function (t) {
    const xyz = new Float32Array(t.count * 3);
    for (let i = 0; i < t.count; ++i) {
      for (let c = 0; c < 3; ++c) xyz[3 * i + c] = t.txyz[4 * i + 1 + c];
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
    // Drawn over the map (no depth test) so walls never hide them: a line
    // and, since WebGL lines are one pixel wide, dots along it; the truth
    // last and narrower, so that an estimate lying on it shows around it.
    const truth = t.name === 'truth';
    const group = new THREE.Group();
    group.add(new THREE.Line(geometry, new THREE.LineBasicMaterial({color: t.color, depthTest: false})));
    group.add(new THREE.Points(geometry, new THREE.PointsMaterial({color: t.color, size: truth ? 2.5 : 4.5,
                                                                   sizeAttenuation: false, depthTest: false})));
    group.children.forEach(c => { c.renderOrder = truth ? 3 : 2; });
    group.geometry = geometry;  // the layer's points, for the browser test
    this.scene.add(group);
    this.layers[t.name] = group;
    geometry.computeBoundingBox();
    this.bounds.union(geometry.boundingBox);
  };

  Viewer.prototype.addLoops = function (loops) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(loops.xyz, 3));
    const material = new THREE.LineBasicMaterial({color: 0xff3df2, depthTest: false});
    const segments = new THREE.LineSegments(geometry, material);
    segments.renderOrder = 4;
    this.scene.add(segments);
    this.layers.loops = segments;
  };

  // A grid on the floor (the lowest z), cells of a round number of metres.
  Viewer.prototype.addGrid = function () {
    const size = this.bounds.getSize(new THREE.Vector3());
    const extent = Math.max(size.x, size.y, 1);
    const cell = Math.pow(10, Math.floor(Math.log10(extent / 5)));
    const divisions = Math.ceil(extent / cell) + 2;
    const grid = new THREE.GridHelper(divisions * cell, divisions, 0x3a4250, 0x262c36);
    grid.rotation.x = Math.PI / 2;
    const center = this.bounds.getCenter(new THREE.Vector3());
    grid.position.set(center.x, center.y, this.bounds.min.z);
    this.scene.add(grid);
    this.layers.grid = grid;
    this.gridCellM = cell;
  };

  // Colours the map by 'height', 'intensity' or 'error'; returns the legend [lo, hi, unit].
  Viewer.prototype.colorBy = function (mode) {
    const map = this.layers.map;
    if (!map) return null;
    const n = this.mapData.shown;
    const values = new Float32Array(n);
    if (mode === 'height') for (let i = 0; i < n; ++i) values[i] = this.mapData.xyz[3 * i + 2];
    else if (mode === 'intensity') values.set(this.mapData.intensity);
    else values.set(this.mapData.error);
    const range = mode === 'error' ? [0, robustRange(values, 2)[1]] : robustRange(values, 2);
    const colors = map.geometry.attributes.color.array;
    const ramp = mode === 'error' ? 'error' : 'viridis';
    for (let i = 0; i < n; ++i) rampColor(ramp, (values[i] - range[0]) / (range[1] - range[0]), colors, 3 * i);
    map.geometry.attributes.color.needsUpdate = true;
    this.render();
    return {lo: range[0], hi: range[1], ramp: ramp, unit: mode === 'intensity' ? '' : 'm'};
  };

  Viewer.prototype.resize = function () {
    const w = this.container.clientWidth || 800, h = this.container.clientHeight || 500;
    this.renderer.setSize(w, h);
    this.aspect = w / h;
    if (this.camera) this.fitCamera();
  };

  // view: '3d' (perspective, orbit), 'top' (x-y) or 'side' (x-z), both orthographic at equal scale.
  Viewer.prototype.setView = function (view) {
    this.view = view;
    if (this.controls) this.controls.dispose();
    if (view === '3d') {
      this.camera = new THREE.PerspectiveCamera(50, this.aspect, 0.01, 1e6);
      this.camera.up.set(0, 0, 1);
    } else {
      this.camera = new THREE.OrthographicCamera(-1, 1, 1, -1, -1e6, 1e6);
      this.camera.up.set(0, view === 'top' ? 1 : 0, view === 'top' ? 0 : 1);
    }
    this.controls = new THREE.OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableRotate = view === '3d';
    this.controls.screenSpacePanning = true;
    this.controls.addEventListener('change', () => this.render());
    this.fitCamera();
  };

  Viewer.prototype.fitCamera = function () {
    const center = this.bounds.getCenter(new THREE.Vector3());
    const size = this.bounds.getSize(new THREE.Vector3());
    const radius = Math.max(size.length() / 2, 0.5);
    if (this.view === '3d') {
      this.camera.aspect = this.aspect;
      this.camera.position.set(center.x - 0.45 * radius, center.y - 1.0 * radius, center.z + 0.7 * radius);
      this.camera.near = radius / 1000;
      this.camera.far = radius * 100;
    } else {
      const w = size.x, h = this.view === 'top' ? size.y : size.z;
      const half = 0.53 * Math.max(w, h * this.aspect, 0.5);
      this.camera.left = -half;
      this.camera.right = half;
      this.camera.top = half / this.aspect;
      this.camera.bottom = -half / this.aspect;
      this.camera.zoom = 1;
      if (this.view === 'top') this.camera.position.set(center.x, center.y, center.z + 10 * radius);
      else this.camera.position.set(center.x, center.y - 10 * radius, center.z);
    }
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.render();
  };

  Viewer.prototype.setVisible = function (name, visible) {
    if (this.layers[name]) this.layers[name].visible = visible;
    this.render();
  };

  Viewer.prototype.setPointSize = function (size) {
    if (this.layers.map) this.layers.map.material.size = size;
    this.render();
  };

  // Hides the map's points above z_m (a ceiling that hides the inside of a tunnel or a building).
  Viewer.prototype.setHeightCut = function (z_m) {
    if (this.heightCut) this.heightCut.constant = z_m;
    this.render();
  };

  Viewer.prototype.render = function () {
    if (this.camera) this.renderer.render(this.scene, this.camera);
  };

  // The visible trajectory sample nearest to canvas pixel (x, y), within
  // maxPixels: {trajectory, t, x, y, z} or null.
  Viewer.prototype.pick = function (x, y, maxPixels) {
    const w = this.renderer.domElement.clientWidth, h = this.renderer.domElement.clientHeight;
    const v = new THREE.Vector3();
    let best = null, bestD2 = maxPixels * maxPixels;
    for (const t of this.trajectories) {
      if (!this.layers[t.name] || !this.layers[t.name].visible) continue;
      for (let i = 0; i < t.count; ++i) {
        v.set(t.txyz[4 * i + 1], t.txyz[4 * i + 2], t.txyz[4 * i + 3]).project(this.camera);
        if (v.z < -1 || v.z > 1) continue;
        const dx = (v.x + 1) / 2 * w - x, dy = (1 - v.y) / 2 * h - y;
        const d2 = dx * dx + dy * dy;
        if (d2 < bestD2) {
          bestD2 = d2;
          best = {trajectory: t.label, t: t.txyz[4 * i], x: t.txyz[4 * i + 1], y: t.txyz[4 * i + 2], z: t.txyz[4 * i + 3]};
        }
      }
    }
    return best;
  };

  Viewer.rampColor = rampColor;
  window.UnimapViewer = Viewer;
})();
