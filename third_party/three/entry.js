// What uvtk's 3D view (inspect/viewer/viewer.js) uses of three.js, as the global THREE.
export {
  BufferAttribute, BufferGeometry, DoubleSide, GLSL3, LineBasicMaterial, LineSegments, LinearMipmapLinearFilter,
  LinearSRGBColorSpace, Mesh, PerspectiveCamera, Raycaster, RepeatWrapping, Scene, ShaderMaterial, Texture, Vector2,
  Vector3, WebGLRenderer
} from 'three';
export { OrbitControls } from 'three/addons/controls/OrbitControls.js';
