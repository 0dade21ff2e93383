// ceilplan's report viewer (docs/report.md): reads the JSON block #ceilplan-data and draws it with
// three.js r111. window.ceilplanReport exposes what a test or a user's script needs: ready,
// planNames, setPlan(name), hoverTime(t_s), markerPosition(), cameraPosition(), view(preset), stats.
(function () {
  'use strict';

  var data = JSON.parse(document.getElementById('ceilplan-data').textContent);
  var api = (window.ceilplanReport = { ready: false, planNames: data.plans.map(function (p) { return p.name; }) });

  // --- Colour maps (stops sampled from matplotlib's viridis and plasma) -------------------------
  var VIRIDIS = [[68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141], [39, 173, 129],
                 [92, 200, 99], [170, 220, 50], [253, 231, 37]];
  var PLASMA = [[13, 8, 135], [106, 0, 168], [177, 42, 144], [225, 100, 98], [252, 166, 54], [240, 249, 33]];
  var STRUCTURE = [[84, 94, 106], [140, 143, 140], [205, 190, 160], [232, 222, 200]];

  function ramp(stops, u) {
    u = Math.min(1, Math.max(0, isFinite(u) ? u : 0));
    var x = u * (stops.length - 1), i = Math.min(stops.length - 2, Math.floor(x)), f = x - i;
    var a = stops[i], b = stops[i + 1];
    return [(a[0] + (b[0] - a[0]) * f) / 255, (a[1] + (b[1] - a[1]) * f) / 255, (a[2] + (b[2] - a[2]) * f) / 255];
  }
  function css(rgb) {
    return 'rgb(' + rgb.map(function (c) { return Math.round(c * 255); }).join(',') + ')';
  }
  function gradient(stops) {
    var parts = [];
    for (var k = 0; k <= 10; ++k) parts.push(css(ramp(stops, k / 10)) + ' ' + k * 10 + '%');
    return 'linear-gradient(to right,' + parts.join(',') + ')';
  }
  function fmt(value, digits) { return Number(value).toFixed(digits); }
  function v3(a) { return new THREE.Vector3(a[0], a[1], a[2]); }

  // --- Samples per plan, as arrays ---------------------------------------------------------------
  var plans = data.plans.map(function (p) {
    var s = p.samples;
    return { source: p, t: s.t, x: s.x, y: s.y, z: s.z, current: s.current, soc: s.soc, sortie: s.sortie };
  });
  var currentMin = Infinity, currentMax = -Infinity, tMax = 0, socMin = 1;
  var bounds = new THREE.Box3();
  bounds.expandByPoint(v3(data.home));
  plans.forEach(function (p) {
    for (var i = 0; i < p.t.length; ++i) {
      currentMin = Math.min(currentMin, p.current[i]);
      currentMax = Math.max(currentMax, p.current[i]);
      socMin = Math.min(socMin, p.soc[i]);
      bounds.expandByPoint(new THREE.Vector3(p.x[i], p.y[i], p.z[i]));
    }
    tMax = Math.max(tMax, p.t[p.t.length - 1]);
  });
  if (!(currentMax > currentMin)) currentMax = currentMin + 1;
  var centre = bounds.getCenter(new THREE.Vector3());
  var extent = bounds.getSize(new THREE.Vector3());
  var span = Math.max(5, extent.x, extent.y, extent.z);
  var mark = Math.max(1, span / 40);  // markers grow with the scene, so they stay visible

  // --- Renderer, camera, controls ----------------------------------------------------------------
  var view = document.getElementById('view');
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  view.insertBefore(renderer.domElement, view.firstChild);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xeef1f4);
  var camera = new THREE.PerspectiveCamera(40, 1, 0.05, 50 * span);
  camera.up.set(0, 0, 1);  // the map frame: z up
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.screenSpacePanning = true;
  controls.addEventListener('change', render);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x6b7785, 0.85));
  var sun = new THREE.DirectionalLight(0xffffff, 0.55);
  sun.position.set(0.4, -0.7, 1.0);
  scene.add(sun);

  // Renders at most once per frame, however many events ask for it.
  var renderPending = false;
  function render() {
    if (renderPending) return;
    renderPending = true;
    window.requestAnimationFrame(function () {
      renderPending = false;
      renderer.render(scene, camera);
      if (!api.ready) {  // the first frame is drawn
        api.ready = true;
        document.body.setAttribute('data-ready', '1');
      }
    });
  }

  // --- Structure: the voxels' visible faces, instanced, shaded by height -----------------------
  // Each cell is [i, j, k, faces]: steps of voxel_m from the origin, and bits -x +x -y +y -z +z
  // for the faces that look onto free space. One instanced square per face.
  var structure = null;
  (function () {
    var s = data.structure, n = s.cells.length / 4, faces = 0, k, b;
    if (!n) return;
    var NORMALS = [[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]];
    var zLow = Infinity, zHigh = -Infinity;
    for (k = 0; k < n; ++k) {
      var z = s.origin[2] + s.cells[4 * k + 2] * s.voxel_m;
      zLow = Math.min(zLow, z);
      zHigh = Math.max(zHigh, z);
      for (b = 0; b < 6; ++b) faces += (s.cells[4 * k + 3] >> b) & 1;
    }
    var offsets = new Float32Array(3 * faces), normals = new Float32Array(3 * faces), colours = new Float32Array(3 * faces);
    var f = 0;
    for (k = 0; k < n; ++k) {
      var centre = [0, 1, 2].map(function (a) { return s.origin[a] + s.cells[4 * k + a] * s.voxel_m; });
      var c = ramp(STRUCTURE, (centre[2] - zLow) / Math.max(zHigh - zLow, 1e-6));
      for (b = 0; b < 6; ++b) {
        if (!((s.cells[4 * k + 3] >> b) & 1)) continue;
        for (var a = 0; a < 3; ++a) {
          offsets[3 * f + a] = centre[a] + 0.5 * s.voxel_m * NORMALS[b][a];
          normals[3 * f + a] = NORMALS[b][a];
        }
        colours.set(c, 3 * f);
        ++f;
      }
    }
    var square = new THREE.PlaneBufferGeometry(1, 1);
    var geometry = new THREE.InstancedBufferGeometry();
    geometry.setIndex(square.index);
    geometry.setAttribute('position', square.attributes.position);
    geometry.setAttribute('offset', new THREE.InstancedBufferAttribute(offsets, 3));
    geometry.setAttribute('faceNormal', new THREE.InstancedBufferAttribute(normals, 3));
    geometry.setAttribute('instanceColour', new THREE.InstancedBufferAttribute(colours, 3));
    geometry.maxInstancedCount = faces;
    var material = new THREE.ShaderMaterial({
      uniforms: { size: { value: s.voxel_m } },
      side: THREE.DoubleSide,
      vertexShader: [
        'attribute vec3 offset;', 'attribute vec3 faceNormal;', 'attribute vec3 instanceColour;', 'uniform float size;',
        'varying vec3 vColour;', 'varying vec3 vNormal;',
        'void main() {',
        '  vec3 a = abs(faceNormal);',
        '  vec3 u = a.x > 0.5 ? vec3(0.0, 1.0, 0.0) : (a.y > 0.5 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0));',
        '  vec3 v = cross(faceNormal, u);',
        '  vColour = instanceColour;',
        '  vNormal = normalize(normalMatrix * faceNormal);',
        '  vec3 p = offset + (position.x * u + position.y * v) * size;',
        '  gl_Position = projectionMatrix * modelViewMatrix * vec4(p, 1.0);',
        '}'].join('\n'),
      fragmentShader: [
        'varying vec3 vColour;', 'varying vec3 vNormal;',
        'void main() {',
        '  vec3 n = normalize(vNormal);',
        '  float light = 0.42 + 0.4 * abs(n.z) + 0.18 * abs(dot(n, normalize(vec3(0.5, 0.8, 0.3))));',
        '  gl_FragColor = vec4(vColour * light, 1.0);',
        '}'].join('\n')
    });
    structure = new THREE.Mesh(geometry, material);
    structure.frustumCulled = false;  // the bounds of one unit square say nothing about the instances
    scene.add(structure);
    api.faces = faces;
  })();

  // --- Routes coloured by current ----------------------------------------------------------------
  // A tube along the points, its rings carried along by parallel transport so it does not twist.
  function tube(points, colours, radius) {
    var sides = 8, positions = [], cols = [], indices = [];
    var normal = new THREE.Vector3(), previous = null;
    for (var i = 0; i < points.length; ++i) {
      var t = points[Math.min(i + 1, points.length - 1)].clone().sub(points[Math.max(i - 1, 0)]).normalize();
      if (previous === null) {
        normal.set(0, 0, 1);
        if (Math.abs(t.z) > 0.9) normal.set(1, 0, 0);
      }
      normal.sub(t.clone().multiplyScalar(t.dot(normal))).normalize();
      var binormal = new THREE.Vector3().crossVectors(t, normal);
      for (var k = 0; k < sides; ++k) {
        var a = 2 * Math.PI * k / sides;
        var p = points[i].clone().addScaledVector(normal, radius * Math.cos(a)).addScaledVector(binormal, radius * Math.sin(a));
        positions.push(p.x, p.y, p.z);
        cols.push(colours[i][0], colours[i][1], colours[i][2]);
      }
      if (i > 0)
        for (k = 0; k < sides; ++k) {
          var a0 = (i - 1) * sides + k, a1 = (i - 1) * sides + (k + 1) % sides, b0 = i * sides + k, b1 = i * sides + (k + 1) % sides;
          indices.push(a0, b0, a1, a1, b0, b1);
        }
      previous = t;
    }
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    g.setAttribute('color', new THREE.Float32BufferAttribute(cols, 3));
    g.setIndex(indices);
    g.computeVertexNormals();
    return g;
  }

  var sphere = new THREE.SphereBufferGeometry(1, 16, 12);
  function ball(position, radius, colour) {
    var m = new THREE.Mesh(sphere, new THREE.MeshLambertMaterial({ color: colour }));
    m.position.copy(position);
    m.scale.setScalar(radius);
    return m;
  }

  // Camera pyramid of a photo: apex at the camera, base `range` ahead.
  function frustumSegments(photo, out) {
    var yaw = photo.yaw_deg * Math.PI / 180, pitch = photo.pitch_deg * Math.PI / 180;
    var forward = new THREE.Vector3(Math.sin(yaw) * Math.cos(pitch), Math.cos(yaw) * Math.cos(pitch), Math.sin(pitch));
    var right = new THREE.Vector3(Math.cos(yaw), -Math.sin(yaw), 0);
    var up = new THREE.Vector3().crossVectors(right, forward);
    var apex = v3(photo.p), r = photo.range_m;
    var w = r * Math.tan(photo.hfov_deg * Math.PI / 360), h = r * Math.tan(photo.vfov_deg * Math.PI / 360);
    var corners = [[1, 1], [1, -1], [-1, -1], [-1, 1]].map(function (s) {
      return apex.clone().addScaledVector(forward, r).addScaledVector(right, s[0] * w).addScaledVector(up, s[1] * h);
    });
    for (var k = 0; k < 4; ++k) {
      out.push(apex.x, apex.y, apex.z, corners[k].x, corners[k].y, corners[k].z);
      var n = corners[(k + 1) % 4];
      out.push(corners[k].x, corners[k].y, corners[k].z, n.x, n.y, n.z);
    }
  }

  function coverageMesh(coverage) {
    var finite = coverage.patches.filter(function (p) { return p.v !== null; }).map(function (p) { return p.v; });
    var low = finite.length ? Math.min.apply(null, finite) : 0, high = finite.length ? Math.max.apply(null, finite) : 1;
    if (!(high > low)) high = low + 1;
    var positions = [], cols = [];
    coverage.patches.forEach(function (p) {
      var n = v3(p.n).normalize();
      var u = new THREE.Vector3(1, 0, 0);
      if (Math.abs(n.x) > 0.9) u.set(0, 1, 0);
      u.sub(n.clone().multiplyScalar(n.dot(u))).normalize();
      var w = new THREE.Vector3().crossVectors(n, u), c = v3(p.c).addScaledVector(n, 0.01), h = p.s / 2;
      var q = [[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]];
      var colour = p.v === null ? [0.86, 0.1, 0.1] : ramp(PLASMA, (p.v - low) / (high - low));
      q.forEach(function (s) {
        var v = c.clone().addScaledVector(u, s[0] * h).addScaledVector(w, s[1] * h);
        positions.push(v.x, v.y, v.z);
        cols.push(colour[0], colour[1], colour[2]);
      });
    });
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    g.setAttribute('color', new THREE.Float32BufferAttribute(cols, 3));
    var mesh = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide }));
    mesh.userData = { low: low, high: high };
    return mesh;
  }

  plans.forEach(function (p) {
    var group = new THREE.Group();
    // One tube per sortie; consecutive repeated samples (dwells) once.
    var start = 0;
    while (start < p.t.length) {
      var end = start;
      while (end + 1 < p.t.length && p.sortie[end + 1] === p.sortie[start]) ++end;
      var points = [], colours = [];
      for (var i = start; i <= end; ++i) {
        var q = new THREE.Vector3(p.x[i], p.y[i], p.z[i]);
        if (points.length && q.distanceTo(points[points.length - 1]) < 1e-4) continue;
        points.push(q);
        colours.push(ramp(VIRIDIS, (p.current[i] - currentMin) / (currentMax - currentMin)));
      }
      if (points.length > 1)
        group.add(new THREE.Mesh(tube(points, colours, Math.max(0.04, span / 350)),
                                 new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors })));
      start = end + 1;
    }
    p.source.targets.forEach(function (t) {
      group.add(ball(v3(t.point), 0.09 * mark, 0xd62728));
      if (t.viewpoint) {
        group.add(ball(v3(t.viewpoint), 0.07 * mark, 0x1f77b4));
        var g = new THREE.BufferGeometry().setFromPoints([v3(t.point), v3(t.viewpoint)]);
        group.add(new THREE.Line(g, new THREE.LineBasicMaterial({ color: 0x1f77b4 })));
      }
    });
    if (p.source.photos.length) {
      var segments = [];
      p.source.photos.forEach(function (photo) { frustumSegments(photo, segments); });
      var fg = new THREE.BufferGeometry();
      fg.setAttribute('position', new THREE.Float32BufferAttribute(segments, 3));
      group.add(new THREE.LineSegments(fg, new THREE.LineBasicMaterial({ color: 0xc2410c })));
    }
    if (p.source.coverage.patches.length) {
      p.coverage = coverageMesh(p.source.coverage);
      group.add(p.coverage);
    }
    p.group = group;
    scene.add(group);
  });

  // Home: a black cone standing on it.
  var home = new THREE.Mesh(new THREE.ConeBufferGeometry(0.25 * mark, 0.6 * mark, 16), new THREE.MeshLambertMaterial({ color: 0x111111 }));
  home.rotation.x = -Math.PI / 2;  // point down onto home
  home.position.copy(v3(data.home)).add(new THREE.Vector3(0, 0, 0.3 * mark));
  scene.add(home);

  // The place the chart points at.
  var marker = ball(new THREE.Vector3(), 0.2 * mark, 0xffb000);
  marker.material.depthTest = false;  // seen through the structure
  marker.renderOrder = 10;
  marker.visible = false;
  scene.add(marker);

  // --- Panels ------------------------------------------------------------------------------------
  var active = 0;
  document.getElementById('title').textContent = data.title;
  document.title = data.title;

  function table(header, rows) {
    var html = '<table>';
    if (header && header.length) html += '<tr>' + header.map(function (h) { return '<th>' + escapeHtml(h) + '</th>'; }).join('') + '</tr>';
    rows.forEach(function (r) { html += '<tr>' + r.map(function (c) { return '<td>' + escapeHtml(c) + '</td>'; }).join('') + '</tr>'; });
    return html + '</table>';
  }
  function escapeHtml(text) {
    return String(text).replace(/[&<>"]/g, function (c) { return { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]; });
  }

  function sortieSpans(p) {
    var spans = [], start = 0;
    for (var i = 1; i <= p.t.length; ++i)
      if (i === p.t.length || p.sortie[i] !== p.sortie[start]) {
        spans.push({ sortie: p.sortie[start], t0: p.t[start], t1: p.t[i - 1], soc0: p.soc[start], soc1: p.soc[i - 1] });
        start = i;
      }
    return spans;
  }

  function updatePanels() {
    var p = plans[active], s = p.source;
    var rows = s.summary.slice();
    sortieSpans(p).forEach(function (span) {
      rows.push(['sortie ' + span.sortie, fmt(span.t0, 0) + '-' + fmt(span.t1, 0) + ' s, SOC ' + fmt(100 * span.soc0, 1) +
                 ' -> ' + fmt(100 * span.soc1, 1) + ' %']);
    });
    document.getElementById('summary').innerHTML = '<h2>' + escapeHtml(s.name) + ' plan</h2>' + table([], rows);
    var comparison = document.getElementById('comparison');
    comparison.innerHTML = data.comparison.rows.length ? '<h2>comparison</h2>' + table(data.comparison.header, data.comparison.rows) : '';
    document.getElementById('help').innerHTML = '<h2>view</h2><p>Left drag: orbit. Right drag or shift+drag: pan. ' +
      'Wheel: zoom. Hover the chart to find a moment on the route.</p>';
    var legend = '<div>current [A]</div><div class="bar" style="background:' + gradient(VIRIDIS) + '"></div>' +
      '<div class="row"><span>' + fmt(currentMin, 2) + '</span><span style="flex:1"></span><span>' + fmt(currentMax, 2) + '</span></div>' +
      '<div class="row"><span class="dot" style="background:#d62728"></span>target' +
      '<span class="dot" style="background:#1f77b4"></span>viewpoint<span class="dot" style="background:#111"></span>home</div>';
    if (s.photos.length) legend += '<div class="row"><span class="dot" style="background:#c2410c"></span>' + s.photos.length + ' photo frusta</div>';
    if (p.coverage)
      legend += '<div>' + escapeHtml(s.coverage.label) + ' (red: not covered)</div><div class="bar" style="background:' + gradient(PLASMA) + '"></div>' +
        '<div class="row"><span>' + fmt(p.coverage.userData.low, 2) + '</span><span style="flex:1"></span><span>' + fmt(p.coverage.userData.high, 2) + '</span></div>';
    if (structure) legend += '<div class="row"><span class="bar" style="width:60px;background:' + gradient(STRUCTURE) + '"></span>structure by height</div>';
    document.getElementById('legend').innerHTML = legend;
  }

  function setPlan(index) {
    active = index;
    plans.forEach(function (p, k) { p.group.visible = k === active; });
    Array.prototype.forEach.call(document.querySelectorAll('#modes button'), function (b, k) { b.classList.toggle('active', k === active); });
    marker.visible = false;
    updatePanels();
    drawChart(null);
    render();
  }

  var modes = document.getElementById('modes');
  plans.forEach(function (p, k) {
    var b = document.createElement('button');
    b.textContent = p.source.name + ' mode';
    b.addEventListener('click', function () { setPlan(k); });
    modes.appendChild(b);
  });

  // --- Camera presets ----------------------------------------------------------------------------
  function look(offset) {
    controls.target.copy(centre);
    camera.position.copy(centre).add(offset.multiplyScalar(span));
    camera.updateProjectionMatrix();
    controls.update();
    render();
  }
  var presets = {
    'below-side': function () { look(new THREE.Vector3(-0.38, -0.62, -0.12)); },
    side: function () { look(new THREE.Vector3(0, -1.25, 0.02)); },
    below: function () { look(new THREE.Vector3(-0.15, -0.35, -0.9)); },
    top: function () { look(new THREE.Vector3(0, -0.05, 1.3)); }
  };
  var buttons = document.getElementById('viewbuttons');
  Object.keys(presets).forEach(function (name) {
    var b = document.createElement('button');
    b.textContent = name;
    b.addEventListener('click', presets[name]);
    buttons.appendChild(b);
  });
  if (structure) {
    var label = document.createElement('label');
    label.innerHTML = '<input type="checkbox" checked> structure';
    label.firstChild.addEventListener('change', function (e) { structure.visible = e.target.checked; render(); });
    buttons.appendChild(label);
  }

  // --- SOC chart, linked to the 3D view ----------------------------------------------------------
  var chart = document.getElementById('chart');
  var ctx = chart.getContext('2d');
  var margin = { left: 48, right: 70, top: 12, bottom: 28 };
  // The SOC axis spans the data, down to the reserve when it is close.
  var socLow = Math.max(0, Math.floor((socMin - 0.03) * 20) / 20);
  if (data.reserve_soc < socLow && data.reserve_soc > socLow - 0.15) socLow = Math.floor(data.reserve_soc * 20) / 20;
  function xOf(t) { return margin.left + (chart.clientWidth - margin.left - margin.right) * t / Math.max(tMax, 1e-9); }
  function yOf(soc) { return margin.top + (chart.clientHeight - margin.top - margin.bottom) * (1 - (soc - socLow) / (1 - socLow)); }
  function tOf(x) { return (x - margin.left) / (chart.clientWidth - margin.left - margin.right) * tMax; }

  function drawChart(hoverT) {
    var w = chart.clientWidth, h = chart.clientHeight, ratio = window.devicePixelRatio || 1;
    if (chart.width !== Math.round(w * ratio) || chart.height !== Math.round(h * ratio)) {
      chart.width = Math.round(w * ratio);
      chart.height = Math.round(h * ratio);
    }
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, w, h);
    ctx.font = '11px system-ui, sans-serif';
    ctx.fillStyle = '#1d232a';
    ctx.strokeStyle = '#c9ced4';
    ctx.lineWidth = 1;
    // Axes and ticks.
    var socStep = 1 - socLow > 0.5 ? 0.1 : 0.05;
    for (var soc = Math.ceil(socLow / socStep - 1e-9) * socStep; soc <= 1.0001; soc += socStep) {
      ctx.beginPath(); ctx.moveTo(margin.left, yOf(soc)); ctx.lineTo(w - margin.right, yOf(soc)); ctx.stroke();
      ctx.fillText(fmt(100 * soc, 0) + ' %', 6, yOf(soc) + 4);
    }
    var step = Math.pow(10, Math.floor(Math.log10(Math.max(tMax, 1) / 5)));
    if (tMax / step > 10) step *= 2;
    if (tMax / step > 10) step *= 2.5;
    for (var t = 0; t <= tMax + 1e-9; t += step) ctx.fillText(fmt(t, 0), xOf(t) - 8, h - 10);
    ctx.fillText('time [s]', w - margin.right + 14, h - 10);
    // Reserve, where the axis reaches it.
    if (data.reserve_soc >= socLow) {
      ctx.strokeStyle = '#d62728';
      ctx.setLineDash([4, 3]);
      ctx.beginPath(); ctx.moveTo(margin.left, yOf(data.reserve_soc)); ctx.lineTo(w - margin.right, yOf(data.reserve_soc)); ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = '#d62728';
      ctx.fillText('reserve', w - margin.right + 6, yOf(data.reserve_soc) + 4);
    } else {
      ctx.fillStyle = '#d62728';
      ctx.fillText('reserve ' + fmt(100 * data.reserve_soc, 0) + ' % below', w - margin.right - 110, h - margin.bottom - 6);
    }
    // Sortie boundaries of the active plan.
    ctx.strokeStyle = '#7b8794';
    ctx.setLineDash([2, 3]);
    sortieSpans(plans[active]).slice(1).forEach(function (span) {
      ctx.beginPath(); ctx.moveTo(xOf(span.t0), margin.top); ctx.lineTo(xOf(span.t0), h - margin.bottom); ctx.stroke();
    });
    ctx.setLineDash([]);
    // SOC: the active plan bold, the others thin.
    plans.forEach(function (p, k) {
      ctx.strokeStyle = k === active ? '#1d6fa5' : '#9aa5b1';
      ctx.lineWidth = k === active ? 2 : 1;
      ctx.beginPath();
      for (var i = 0; i < p.t.length; ++i) {
        if (i === 0 || p.sortie[i] !== p.sortie[i - 1]) ctx.moveTo(xOf(p.t[i]), yOf(p.soc[i]));
        else ctx.lineTo(xOf(p.t[i]), yOf(p.soc[i]));
      }
      ctx.stroke();
      ctx.fillStyle = ctx.strokeStyle;
      ctx.fillText(p.source.name, xOf(p.t[p.t.length - 1]) + 6, yOf(p.soc[p.soc.length - 1]) + 4 + 12 * (k - active));
    });
    ctx.lineWidth = 1;
    if (hoverT !== null) {
      ctx.strokeStyle = '#ffb000';
      ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(xOf(hoverT), margin.top); ctx.lineTo(xOf(hoverT), h - margin.bottom); ctx.stroke();
      ctx.lineWidth = 1;
    }
  }

  // The sample of the active plan at time t (the last at or before it).
  function sampleAt(t) {
    var p = plans[active], lo = 0, hi = p.t.length - 1;
    if (t <= p.t[0]) return 0;
    while (lo < hi) {
      var mid = (lo + hi + 1) >> 1;
      if (p.t[mid] <= t) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  function hoverTime(t) {
    t = Math.min(Math.max(t, 0), tMax);
    var p = plans[active], i = sampleAt(t);
    marker.position.set(p.x[i], p.y[i], p.z[i]);
    marker.visible = true;
    var tip = document.getElementById('tooltip');
    tip.style.display = 'block';
    tip.textContent = 't ' + fmt(p.t[i], 1) + ' s, sortie ' + p.sortie[i] + ', SOC ' + fmt(100 * p.soc[i], 1) + ' %, ' +
      fmt(p.current[i], 2) + ' A at (' + fmt(p.x[i], 2) + ', ' + fmt(p.y[i], 2) + ', ' + fmt(p.z[i], 2) + ')';
    drawChart(t);
    render();
    return { index: i, position: [p.x[i], p.y[i], p.z[i]] };
  }

  chart.addEventListener('mousemove', function (e) {
    var rect = chart.getBoundingClientRect();
    hoverTime(tOf(e.clientX - rect.left));
  });
  chart.addEventListener('mouseleave', function () {
    marker.visible = false;
    document.getElementById('tooltip').style.display = 'none';
    drawChart(null);
    render();
  });

  function resize() {
    var w = view.clientWidth, h = view.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    drawChart(null);
    render();
  }
  window.addEventListener('resize', resize);

  api.setPlan = function (name) {
    var k = api.planNames.indexOf(name);
    if (k < 0) throw new Error('no plan named ' + name);
    setPlan(k);
  };
  api.hoverTime = hoverTime;
  api.view = function (name) { presets[name](); };
  api.markerPosition = function () { return marker.visible ? [marker.position.x, marker.position.y, marker.position.z] : null; };
  api.activePlan = function () { return plans[active].source.name; };
  api.cameraPosition = function () { return [camera.position.x, camera.position.y, camera.position.z]; };
  api.stats = {
    voxels: data.structure.cells.length / 4,
    samples: plans.map(function (p) { return p.t.length; }),
    photos: plans.map(function (p) { return p.source.photos.length; }),
    patches: plans.map(function (p) { return p.source.coverage.patches.length; })
  };

  resize();
  setPlan(0);
  presets['below-side']();
})();
