// uvtk's 3D view (docs/views.md, "The 3D view"): every <div class="view3d"> of the page shows its
// mesh, whose data (inspect/mesh_view.cpp) sits in the div's <script class="view3d-data">: zlib
// streams in base64, read back with the browser's DecompressionStream. three.js is the global THREE
// (third_party/three). Nothing is requested from anywhere.
(function () {
  'use strict';

  async function inflate(base64) {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
    return new Response(stream).arrayBuffer();
  }

  // An IEEE 754 half-precision number (mesh_view.cpp's toHalf).
  function fromHalf(bits) {
    const sign = bits & 0x8000 ? -1 : 1, exponent = (bits >> 10) & 31, fraction = bits & 1023;
    if (exponent === 0) return sign * fraction * Math.pow(2, -24);
    return sign * (1 + fraction / 1024) * Math.pow(2, exponent - 15);
  }

  // Per corner of the non-indexed triangles: the face's colour code looked up in `table`.
  function faceColours(codes, table, out) {
    for (let f = 0; f < codes.length; ++f) {
      const c = table[codes[f]];
      for (let k = 0; k < 3; ++k) out.set(c, 9 * f + 3 * k);
    }
  }

  const vertexShader = `
    in vec3 faceColour;
    out vec2 vUv;
    out vec3 vColour;
    out vec3 vViewPosition;
    void main() {
      vec4 viewPosition = modelViewMatrix * vec4(position, 1.0);
      vUv = uv;
      vColour = faceColour;
      vViewPosition = viewPosition.xyz;
      gl_Position = projectionMatrix * viewPosition;
    }`;

  // mode 0: the checker view's checks (light 230/255, dark 89/255, the light one at u = v = 0),
  // shaded; 1: the UV grid texture as it is; 2: the face's colour, shaded. The shade is a head-light:
  // 0.25 + 0.75 |cos| of the angle between the face's normal and the ray from the eye.
  const fragmentShader = `
    uniform int mode;
    uniform float checks;
    uniform sampler2D grid;
    in vec2 vUv;
    in vec3 vColour;
    in vec3 vViewPosition;
    out vec4 fragColour;
    void main() {
      vec3 normal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
      float shade = 0.25 + 0.75 * abs(dot(normal, normalize(vViewPosition)));
      vec3 colour;
      if (mode == 0) {
        vec2 cell = floor(vUv * checks);
        colour = vec3(mod(cell.x + cell.y, 2.0) < 0.5 ? 230.0 / 255.0 : 89.0 / 255.0) * shade;
      } else if (mode == 1) {
        colour = texture(grid, vUv).rgb;
      } else {
        colour = vColour * shade;
      }
      fragColour = vec4(colour, 1.0);
    }`;

  // 3 significant digits; a half at its largest stands for any value beyond (mesh_view.cpp's toHalf).
  function format(value, half) {
    if (half && Math.abs(value) >= 65504) return (value < 0 ? '<= ' : '>= ') + '65504';
    return Number(value.toPrecision(3)).toString();
  }

  async function start(root) {
    const data = JSON.parse(root.querySelector('script.view3d-data').textContent);
    const blobs = {};
    for (const [name, text] of Object.entries(data.blobs)) blobs[name] = await inflate(text);
    const positions = Float32Array.from(new Uint16Array(blobs.positions), (q) => q / 32767.5 - 1);
    const uvs = new Float32Array(blobs.uvs);
    const indices = new Uint32Array(blobs.indices);
    const status = new Uint8Array(blobs.status);
    const faceOf = blobs.face_of ? new Uint32Array(blobs.face_of) : null;  // when decimated
    const faces = status.length;

    // Non-indexed triangles, so that every face can have its own colour.
    const cornerPositions = new Float32Array(9 * faces);
    const cornerUvs = new Float32Array(6 * faces);
    for (let c = 0; c < 3 * faces; ++c) {
      const v = indices[c];
      cornerPositions.set(positions.subarray(3 * v, 3 * v + 3), 3 * c);
      cornerUvs.set(uvs.subarray(2 * v, 2 * v + 2), 2 * c);
    }
    const colours = new Uint8Array(9 * faces);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(cornerPositions, 3));
    geometry.setAttribute('uv', new THREE.BufferAttribute(cornerUvs, 2));
    const colourAttribute = new THREE.BufferAttribute(colours, 3, true);
    geometry.setAttribute('faceColour', colourAttribute);
    geometry.computeBoundingSphere();

    const gridImage = new Image();
    gridImage.src = data.uvgrid;
    await gridImage.decode();
    const grid = new THREE.Texture(gridImage);
    grid.wrapS = grid.wrapT = THREE.RepeatWrapping;
    grid.minFilter = THREE.LinearMipmapLinearFilter;
    grid.needsUpdate = true;

    const material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      vertexShader,
      fragmentShader,
      uniforms: { mode: { value: 0 }, checks: { value: data.checks }, grid: { value: grid } },
      side: THREE.DoubleSide,
      polygonOffset: true,  // the seam lines stay in front of their faces
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    const mesh = new THREE.Mesh(geometry, material);

    const seamPoints = new Float32Array(blobs.seam_points);
    const seamWrap = new Uint8Array(blobs.seam_wrap);
    const seamColours = new Float32Array(seamPoints.length);
    for (let e = 0; e < seamWrap.length; ++e) {
      const rgb = (seamWrap[e] ? data.seam_colours.wrap : data.seam_colours.cut).map((x) => x / 255);
      seamColours.set(rgb, 6 * e);
      seamColours.set(rgb, 6 * e + 3);
    }
    const seamGeometry = new THREE.BufferGeometry();
    seamGeometry.setAttribute('position', new THREE.BufferAttribute(seamPoints, 3));
    seamGeometry.setAttribute('color', new THREE.BufferAttribute(seamColours, 3));
    const seams = new THREE.LineSegments(seamGeometry, new THREE.LineBasicMaterial({ vertexColors: true }));

    const scene = new THREE.Scene();
    scene.add(mesh);
    scene.add(seams);

    const canvas = root.querySelector('canvas');
    // Opaque, so that the pixels read back from the canvas are what a person sees.
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.outputColorSpace = THREE.LinearSRGBColorSpace;  // colours as the static views have them
    // three.js takes a colour given in hex as sRGB and turns it linear; written out unconverted, sRGB
    // 0x727272 (linear 0.165) is 0x2a2a2a, the canvas background of viewer.css.
    renderer.setClearColor(0x727272, 1);
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 100);
    const controls = new THREE.OrbitControls(camera, canvas);
    const radius = geometry.boundingSphere.radius || 1;
    const home = () => {
      const direction = new THREE.Vector3(...data.view_dir).normalize();
      camera.up.set(...data.up).normalize();
      controls.target.copy(geometry.boundingSphere.center);
      camera.position.copy(controls.target).addScaledVector(direction, 1.1 * radius / Math.sin(Math.PI * 15 / 180));
      camera.near = radius / 100;
      camera.far = radius * 100;
      camera.updateProjectionMatrix();
      controls.update();
    };

    const draw = () => {
      const width = canvas.clientWidth, height = canvas.clientHeight;
      if (canvas.width !== Math.round(width * renderer.getPixelRatio()) ||
          canvas.height !== Math.round(height * renderer.getPixelRatio())) {
        renderer.setSize(width, height, false);
        camera.aspect = width / Math.max(height, 1);
        camera.updateProjectionMatrix();
      }
      renderer.render(scene, camera);
    };
    controls.addEventListener('change', draw);
    new ResizeObserver(draw).observe(canvas);

    // Layers.
    const layers = Object.fromEntries(data.layers.map((layer) => [layer.name, layer]));
    const codes = {};
    for (const name of data.measures) codes[name] = new Uint8Array(blobs['codes_' + name]);
    const values = {};
    for (const name of data.measures) {
      const whole = data.float_measures.includes(name);  // else IEEE halves
      values[name] = whole ? new Float32Array(blobs['values_' + name])
                           : Float32Array.from(new Uint16Array(blobs['values_' + name]), fromHalf);
    }
    const select = root.querySelector('select.layers');
    const legends = root.querySelectorAll('.legend');
    const showLayer = (name) => {
      const layer = layers[name];
      material.uniforms.mode.value = layer.kind === 'checker' ? 0 : layer.kind === 'uvgrid' ? 1 : 2;
      if (layer.kind === 'faces') {
        faceColours(name === 'status' ? status : codes[name], data.tables[name], colours);
        colourAttribute.needsUpdate = true;
      }
      for (const legend of legends) legend.hidden = legend.dataset.layer !== name;
      draw();
    };
    select.addEventListener('change', () => showLayer(select.value));
    const seamBox = root.querySelector('input.show-seams');
    seamBox.addEventListener('change', () => { seams.visible = seamBox.checked; draw(); });
    root.querySelector('button.reset').addEventListener('click', () => { home(); draw(); });

    // The face under the pointer.
    const hover = root.querySelector('.hover');
    const raycaster = new THREE.Raycaster();
    let pointer = null, pending = false;
    const pick = () => {
      pending = false;
      if (!pointer) return;
      const box = canvas.getBoundingClientRect();
      const ndc = new THREE.Vector2(((pointer.x - box.left) / box.width) * 2 - 1, -((pointer.y - box.top) / box.height) * 2 + 1);
      raycaster.setFromCamera(ndc, camera);
      const hit = raycaster.intersectObject(mesh, false)[0];
      if (!hit) return;
      const f = hit.faceIndex, s = status[f];
      let text = 'face ' + (faceOf ? faceOf[f] : f) + ': ' + data.statuses[s];
      if (data.measured[s]) for (const name of data.measures) text += ' \u00b7 ' + name + ' ' + format(values[name][f], !data.float_measures.includes(name));
      if (hit.uv) text += ' \u00b7 uv (' + hit.uv.x.toPrecision(4) + ', ' + hit.uv.y.toPrecision(4) + ')';
      hover.textContent = text;
    };
    canvas.addEventListener('pointermove', (event) => {
      pointer = { x: event.clientX, y: event.clientY };
      if (!pending) { pending = true; requestAnimationFrame(pick); }
    });

    home();
    showLayer(select.value);
    root.dataset.ready = '1';
  }

  for (const root of document.querySelectorAll('.view3d')) {
    start(root).catch((error) => {
      root.dataset.error = String(error && error.message || error);
      const message = document.createElement('p');
      message.className = 'failed';
      message.textContent = 'The 3D view could not start: ' + root.dataset.error;
      root.appendChild(message);
      console.error('uvtk 3D view:', error);
    });
  }
})();
