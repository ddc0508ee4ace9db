//////////////////////////////////////////////////
// Soft shadows (distributed ray tracing): three balls on a plane under a spherical light. Each
// sample of a pixel lights the point from another point of the light, stratified over the pixel's
// samples, so the penumbra grows with the light's radius. Parameter r = radius of the light
// (default 0.8; 0 = a point light with hard shadows).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "r=<double> (radius of the spherical light, default 0.8; 0 = point light)";
context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
context[PropertyName.CTX_SUPERSAMPLING] = 16;

Dictionary<string, string> p = Util.ParseKeyValueList(param);
double r = 0.8;
Util.TryParse(p, "r", ref r);

CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.9, 0.9, 0.85 }, 0.1, 0.8, 0.1, 16));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.05, 0.05, 0.08 };
scene.Camera = new StaticCamera(new Vector3d(0.0, 2.5, -6.5), new Vector3d(0.0, -0.45, 1.0), 50.0);
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.3));
scene.Sources.Add(new SphereLightSource(new Vector3d(-2.0, 4.0, -1.0), r, 1.0));

double[][] colors = { new[] { 0.9, 0.2, 0.2 }, new[] { 0.2, 0.8, 0.3 }, new[] { 0.2, 0.4, 0.9 } };
for (int k = 0; k < 3; k++)
{
  Sphere ball = new Sphere();
  ball.SetAttribute(PropertyName.COLOR, colors[k]);
  root.InsertChild(ball, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(-1.6 + 1.6 * k, -0.4, 0.5 * k));
}

Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.8, 0.8, 0.8 });
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
