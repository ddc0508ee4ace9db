//////////////////////////////////////////////////
// Orbit: an animated scene. The camera circles the scene once (AnimatedCamera) while
// a ball bounces along a Catmull-Rom path (PropertyAnimator + AnimatedNodeTransform).
// Render a still with `grcis render scripts/Orbit.cs --time 1.5`.

Debug.Assert(scene != null);
Debug.Assert(context != null);

double start = 0.0;
double end = 4.0;

// Animation range and frame rate (read by `grcis info` and `grcis animate`).
context[PropertyName.CTX_START_ANIM] = start;
context[PropertyName.CTX_END_ANIM] = end;
context[PropertyName.CTX_FPS] = 12.0;
context[PropertyName.CTX_TOOLTIP] = "no parameters; animated from t = 0 to 4 s";

// The host gives animation scripts an AnimatedRayScene; set its range.
if (scene is ITimeDependent animated)
{
  animated.Start = start;
  animated.End = end;
}

// Animator: the ball's offset, a closed path sampled at five points (played twice over the range).
PropertyAnimator pa = new PropertyAnimator();
pa.Start = start;
pa.End = end;
pa.newProperty<Vector3d>("ball", start, end, 2.0, PropertyAnimator.InterpolationStyle.Cyclic,
  new List<Vector3d>
  {
    new Vector3d(-1.5, 0.0, 0.0),
    new Vector3d(-0.5, 1.5, -0.5),
    new Vector3d(0.8, 0.2, -0.8),
    new Vector3d(1.5, 1.2, 0.5),
    new Vector3d(0.0, 0.6, 1.2),
  }, true);
scene.Animator = pa;

// CSG scene: an animated root passes time on to its animated children.
AnimatedCSGInnerNode root = new AnimatedCSGInnerNode(SetOperation.Union, start, end);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.4, 32));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };

// Camera: circles the point (0, 0.2, 0) once per animation.
AnimatedCamera cam = new AnimatedCamera(new Vector3d(0.0, 0.2, 0.0), new Vector3d(0.0, 2.0, -7.0), 50.0);
cam.Start = start;
cam.End = end;
scene.Camera = cam;

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.2));

// --- NODE DEFINITIONS ----------------------------------------------------

// A fixed centre-piece: a mirror sphere.
Sphere s = new Sphere();
s.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.9, 0.9, 1.0 }, 0.05, 0.2, 0.8, 128));
root.InsertChild(s, Matrix4d.Scale(0.7));

// The bouncing ball: its transform is Scale(0.35) * offset("ball") at every time.
AnimatedNodeTransform ballNode = new AnimatedNodeTransform("ball", null, Matrix4d.Scale(0.35), SetOperation.Union, start, end);
Sphere ball = new Sphere();
ball.SetAttribute(PropertyName.COLOR, new double[] { 0.2, 0.5, 1.0 });
ballNode.InsertChild(ball, Matrix4d.Identity);
root.InsertChild(ballNode, Matrix4d.Scale(0.35));

// Infinite plane with checker.
Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.3, 0.0, 0.0 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.6, 0.6, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
