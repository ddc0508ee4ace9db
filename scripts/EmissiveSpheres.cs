//////////////////////////////////////////////////
// Emissive spheres (path tracing): three small glowing balls light a white floor and a grey ball,
// with no other light. The path tracer samples each sphere by the cone of directions it subtends,
// so the soft shadows converge at a few dozen samples. Linear radiance, so render to PFM:
//   grcis render scripts/EmissiveSpheres.cs --size 320x240 --spp 64 -o spheres.pfm --noise noise.pfm
// Parameters: le = radiance of the spheres (default 30); stretch = vertical scale of the spheres
// (default 1: any other value makes them ellipsoids, which only scattered rays find, e.g. 1.000001
// for the same picture without light sampling).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "le=<double> (radiance of the glowing spheres, default 30), stretch=<double> (vertical scale, default 1; else not light-sampled)";
context[PropertyName.CTX_ALGORITHM] = new PathTracing();
context[PropertyName.CTX_SUPERSAMPLING] = 64;

Dictionary<string, string> p = Util.ParseKeyValueList(param);
double le = 30.0;
Util.TryParse(p, "le", ref le);
double stretch = 1.0;
Util.TryParse(p, "stretch", ref stretch);

// Lambertian surfaces: Kd 1 makes the colour the albedo.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.75, 0.75, 0.75 }, 0.0, 1.0, 0.0, 1));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.0, 0.0, 0.0 };
scene.Camera = new StaticCamera(new Vector3d(0.0, 2.2, -4.0), new Vector3d(0.0, -0.5, 1.0), 50.0);
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();

Plane floor = new Plane();
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2));

Sphere ball = new Sphere();
ball.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.0, 1.0, 0.0, 1));
root.InsertChild(ball, Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(0.0, 0.5, 0.3));

// The lights: black (reflecting nothing); uniformly scaled, so each is sampled directly.
double[][] tints = { new[] { 1.0, 0.55, 0.25 }, new[] { 0.35, 0.6, 1.0 }, new[] { 1.0, 1.0, 1.0 } };
double[][] places = { new[] { -1.1, 0.7, 0.0 }, new[] { 1.1, 0.5, 0.4 }, new[] { 0.5, 1.1, 1.6 } };
double[] radii = { 0.12, 0.1, 0.15 };
for (int k = 0; k < 3; k++)
{
  PhongMaterial glow = new PhongMaterial(new double[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1);
  glow.Emission = new double[] { le * tints[k][0], le * tints[k][1], le * tints[k][2] };
  Sphere light = new Sphere();
  light.SetAttribute(PropertyName.MATERIAL, glow);
  root.InsertChild(light, Matrix4d.Scale(radii[k], radii[k] * stretch, radii[k]) * Matrix4d.CreateTranslation(places[k][0], places[k][1], places[k][2]));
}
