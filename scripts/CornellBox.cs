//////////////////////////////////////////////////
// The Cornell box of the path tracer's benchmark (bench/cornell in the shared folder's
// specification): a box 2 units wide, open towards the camera, lit by a one-sided
// emitter of radiance 15 in a hole of the ceiling. Linear radiance, so render to PFM:
//   grcis render scripts/CornellBox.cs --param "variant=spheres" --size 256x256 --spp 256 -o spheres.pfm
// Parameter variant = diffuse (two white Lambertian spheres, default) or spheres (mirror + glass).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "variant=diffuse|spheres (two white spheres, or a mirror and a glass one)";
context[PropertyName.CTX_WIDTH] = 256;
context[PropertyName.CTX_HEIGHT] = 256;
context[PropertyName.CTX_SUPERSAMPLING] = 16;
context[PropertyName.CTX_ALGORITHM] = new PathTracing();

Dictionary<string, string> p = Util.ParseKeyValueList(param);
string variant = "diffuse";
if (p.TryGetValue("variant", out string v) && !string.IsNullOrWhiteSpace(v))
  variant = v.Trim().ToLowerInvariant().Replace("cornell-", "");
if (variant != "diffuse" && variant != "spheres")
  throw new ArgumentException($"variant={variant}: use variant=diffuse or variant=spheres");

// Lambertian surfaces: Kd 1 makes the colour the albedo (the path tracer's BRDF is albedo/pi).
PhongMaterial Lambert(double r, double g, double b) => new PhongMaterial(new double[] { r, g, b }, 0.0, 1.0, 0.0, 1);
PhongMaterial white = Lambert(0.73, 0.73, 0.73);

CSGInnerNode top = new CSGInnerNode(SetOperation.Union);
top.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
top.SetAttribute(PropertyName.MATERIAL, white);
scene.Intersectable = top;

// The specification is right-handed (+x to the right when looking down -z); GrCis's camera shows
// +x to the right when looking down +z. Mirroring x keeps the specification's numbers below.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
top.InsertChild(root, Matrix4d.Scale(-1.0, 1.0, 1.0));
scene.BackgroundColor = new double[] { 0.0, 0.0, 0.0 };
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();

// Pinhole camera at (0, 1, 3.7) looking down -Z, 40 degrees across the square image.
scene.Camera = new StaticCamera(new Vector3d(0.0, 1.0, 3.7), new Vector3d(0.0, 0.0, -1.0), 40.0);

// A rectangle of the local z = 0 plane (normal +z), placed by a transform.
void Wall(double x0, double x1, double y0, double y1, Matrix4d place, PhongMaterial material)
{
  Plane wall = new Plane(x0, x1, y0, y1);
  wall.SetAttribute(PropertyName.MATERIAL, material);
  root.InsertChild(wall, place);
}

// Floor (normal +y), back wall (+z), left wall red (+x), right wall green (-x).
Wall(-1, 1, -1, 1, Matrix4d.RotateX(-MathHelper.PiOver2), white);
Wall(-1, 1, 0, 2, Matrix4d.CreateTranslation(0, 0, -1), white);
Wall(-1, 1, 0, 2, Matrix4d.RotateY(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-1, 0, 0), Lambert(0.65, 0.05, 0.05));
Wall(-1, 1, 0, 2, Matrix4d.RotateY(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(1, 0, 0), Lambert(0.12, 0.45, 0.15));

// Ceiling at y = 2 facing down (local y becomes world z): four pieces around the light.
Matrix4d ceiling = Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, 2, 0);
Wall(-1, -0.25, -1, 1, ceiling, white);
Wall(0.25, 1, -1, 1, ceiling, white);
Wall(-0.25, 0.25, -1, -0.2, ceiling, white);
Wall(-0.25, 0.25, 0.2, 1, ceiling, white);

// The light: one-sided emission downwards, reflecting nothing.
PhongMaterial emitter = new PhongMaterial(new double[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1);
emitter.Emission = new double[] { 15.0, 15.0, 15.0 };
Wall(-0.25, 0.25, -0.2, 0.2, ceiling, emitter);

// Two spheres of radius 0.4 resting on the floor.
PhongMaterial a = white, b = white;
if (variant == "spheres")
{
  // An exponent this high is an ideal mirror for the path tracer (PathTracing.MirrorExponent).
  a = new PhongMaterial(new double[] { 1.0, 1.0, 1.0 }, 0.0, 0.0, 1.0, 1000000);
  b = new PhongMaterial(new double[] { 1.0, 1.0, 1.0 }, 0.0, 0.0, 0.0, 1);
  b.Kt = 1.0;
  b.n = 1.5;
}
Sphere sa = new Sphere();
sa.SetAttribute(PropertyName.MATERIAL, a);
root.InsertChild(sa, Matrix4d.Scale(0.4) * Matrix4d.CreateTranslation(-0.45, 0.4, -0.35));
Sphere sb = new Sphere();
sb.SetAttribute(PropertyName.MATERIAL, b);
root.InsertChild(sb, Matrix4d.Scale(0.4) * Matrix4d.CreateTranslation(0.45, 0.4, 0.35));
