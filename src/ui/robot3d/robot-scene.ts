/**
 * The HUNO drawn with three.js: the only module of the panel that imports `three`, loaded with `import()` by
 * robot-canvas.ts when a 3D view first appears, so the first page load never carries it.
 *
 * One box per shape of huno-model.ts (plastic shell, servo cases, the visor that shows where the robot faces),
 * a ground grid, soft light from above (a hemisphere light and one directional light), and a camera that turns
 * about the robot. It draws only when asked (`render()`), never in a loop; `dispose()` frees every GPU resource
 * and the WebGL context itself.
 */
import {
  BoxGeometry,
  Color,
  DirectionalLight,
  GridHelper,
  Group,
  HemisphereLight,
  type Material,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  WebGLRenderer,
} from "three";
import { HUNO_SHAPES, type LinkId, type ShapeKind } from "./huno-model.ts";
import type { RobotTransforms } from "./kinematics.ts";

/** CSS colours of the scene (from the page's colour scheme, robot3d.css). */
export interface SceneColours {
  background: string;
  shell: string;
  servo: string;
  visor: string;
  grid: string;
  gridCentre: string;
}

/** Where the camera is: turned `azimuth` radians about the robot from straight ahead, `elevation` above level. */
export interface CameraView {
  azimuth: number;
  elevation: number;
}

export interface RobotSceneHandle {
  setTransforms(t: RobotTransforms): void;
  setView(view: CameraView): void;
  setColours(colours: SceneColours): void;
  /** The canvas's size in CSS pixels, and the device pixel ratio to draw at. */
  setSize(width: number, height: number, pixelRatio: number): void;
  render(): void;
  dispose(): void;
}

/** The point the camera looks at (mm above the ground, in three's y-up frame) and its distance from it. */
const TARGET_HEIGHT = 200;
const CAMERA_DISTANCE = 1000;
const GRID_SIZE = 600;
const GRID_DIVISIONS = 12;

/**
 * Creates the renderer on `canvas`. Throws (three's own error) when no WebGL 2 context can be made; the caller
 * has checked for WebGL 2 first and shows its text instead of the picture.
 */
export function createRobotScene(canvas: HTMLCanvasElement, colours: SceneColours): RobotSceneHandle {
  // preserveDrawingBuffer: the picture stays readable after it is shown (tests and screenshots read it).
  const renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  const scene = new Scene();
  const camera = new PerspectiveCamera(32, 4 / 3, 10, 6000);

  const hemisphere = new HemisphereLight(0xffffff, 0x8a8f96, 2.2);
  const sun = new DirectionalLight(0xffffff, 1.6);
  sun.position.set(400, 900, 600);
  scene.add(hemisphere, sun);

  // The model is z-up (huno-model.ts); three is y-up: turn the robot's frame a quarter turn about x.
  const robot = new Group();
  robot.rotation.x = -Math.PI / 2;
  scene.add(robot);

  const materials: Record<ShapeKind, MeshLambertMaterial> = {
    shell: new MeshLambertMaterial(),
    servo: new MeshLambertMaterial(),
    visor: new MeshLambertMaterial(),
  };
  const geometries: BoxGeometry[] = [];
  const links = new Map<LinkId, Group>();
  for (const [link, shape] of HUNO_SHAPES) {
    let group = links.get(link);
    if (!group) {
      group = new Group();
      group.matrixAutoUpdate = false;
      links.set(link, group);
      robot.add(group);
    }
    const geometry = new BoxGeometry(...shape.size);
    geometries.push(geometry);
    const mesh = new Mesh(geometry, materials[shape.kind]);
    mesh.position.set(...shape.centre);
    group.add(mesh);
  }

  let grid: GridHelper | undefined;
  const makeGrid = (c: SceneColours) => {
    if (grid) {
      scene.remove(grid);
      grid.geometry.dispose();
      (grid.material as Material).dispose();
    }
    grid = new GridHelper(GRID_SIZE, GRID_DIVISIONS, new Color(c.gridCentre), new Color(c.grid));
    scene.add(grid);
  };

  const setColours = (c: SceneColours) => {
    renderer.setClearColor(new Color(c.background), 1);
    materials.shell.color.set(c.shell);
    materials.servo.color.set(c.servo);
    materials.visor.color.set(c.visor);
    makeGrid(c);
  };
  setColours(colours);

  const setView = ({ azimuth, elevation }: CameraView) => {
    const flat = Math.cos(elevation) * CAMERA_DISTANCE;
    camera.position.set(
      Math.cos(azimuth) * flat,
      TARGET_HEIGHT + Math.sin(elevation) * CAMERA_DISTANCE,
      Math.sin(azimuth) * flat,
    );
    camera.lookAt(0, TARGET_HEIGHT, 0);
  };
  setView({ azimuth: 0.75, elevation: 0.25 });

  return {
    setTransforms(t) {
      for (const [link, group] of links) {
        const m = link === "torso" ? t.torso : t.links[link];
        if (!m) continue;
        group.matrix.fromArray(m);
        group.matrixWorldNeedsUpdate = true;
      }
    },
    setView,
    setColours,
    setSize(width, height, pixelRatio) {
      renderer.setPixelRatio(pixelRatio);
      // false: the canvas's CSS size is the style sheet's (robot3d.css), not an inline style.
      renderer.setSize(Math.max(1, Math.round(width)), Math.max(1, Math.round(height)), false);
      camera.aspect = width > 0 && height > 0 ? width / height : 4 / 3;
      camera.updateProjectionMatrix();
    },
    render() {
      renderer.render(scene, camera);
    },
    dispose() {
      for (const g of geometries) g.dispose();
      for (const m of Object.values(materials)) m.dispose();
      if (grid) {
        grid.geometry.dispose();
        (grid.material as Material).dispose();
      }
      scene.clear();
      renderer.dispose();
      // Frees the context now rather than when the canvas is collected: a browser keeps only so many.
      renderer.forceContextLoss();
    },
  };
}
