//////////////////////////////////////////////////
// Depth of field (distributed ray tracing): a row of balls running away from a thin-lens camera
// focused on the third one. Nearer and farther balls blur more with a larger lens. Parameters
// lens = radius of the lens aperture (default 0.15; 0 = pinhole, all sharp), focus = distance of
// the plane in focus (default: the third ball).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "lens=<double> (aperture radius, default 0.15), focus=<double> (focus distance, default: the third ball)";
context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
context[PropertyName.CTX_SUPERSAMPLING] = 16;

Dictionary<string, string> p = Util.ParseKeyValueList(param);
double lens = 0.15;
Util.TryParse(p, "lens", ref lens);

CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.3, 32));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.2));

Vector3d eye = new Vector3d(2.2, 0.6, -5.0);
Vector3d[] centres = new Vector3d[6];
for (int k = 0; k < centres.Length; k++)
{
  centres[k] = new Vector3d(0.0, -0.5, -3.0 + 2.5 * k);
  Sphere ball = new Sphere();
  ball.SetAttribute(PropertyName.COLOR, new double[] { 0.3 + 0.12 * k, 0.8 - 0.1 * k, 0.2 + 0.1 * k });
  root.InsertChild(ball, Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(centres[k]));
}

ThinLensCamera camera = new ThinLensCamera(eye, centres[2] - eye + new Vector3d(0.0, 0.3, 3.0), 45.0);
camera.LensRadius = lens;
camera.FocusOn(centres[2]);
double focus = camera.FocusDistance;
Util.TryParse(p, "focus", ref focus);
camera.FocusDistance = focus;
scene.Camera = camera;

Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.3, 0.0, 0.0 });
floor.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.6, 0.6, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
