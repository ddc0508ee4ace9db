//////////////////////////////////////////////////
// Panorama: a 360-degree equirectangular camera declared in the script (a class
// implementing ICamera, declared after its use). The image spans all longitudes
// (left to right) and latitudes (top to bottom), so it is twice as wide as high.

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_WIDTH] = 720;
context[PropertyName.CTX_HEIGHT] = 360;
context[PropertyName.CTX_TOOLTIP] = "count=<int> (balls around the viewer, default 12)";

Dictionary<string, string> p = Util.ParseKeyValueList(param);
int count = 12;
Util.TryParse(p, "count", ref count);

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.15, 0.7, 0.3, 32));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.3, 0.5, 0.8 };

// Camera: the class is declared at the end of the script.
scene.Camera = new EquirectangularCamera(new Vector3d(0.0, 0.5, 0.0));

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.7));
scene.Sources.Add(new PointLightSource(new Vector3d(0.0, 6.0, 0.0), 1.0));

// --- NODE DEFINITIONS ----------------------------------------------------

// A ring of coloured balls around the viewer.
for (int i = 0; i < count; i++)
{
  double a = 2.0 * Math.PI * i / count;
  Sphere s = new Sphere();
  s.SetAttribute(PropertyName.COLOR, new double[] { 0.5 + 0.5 * Math.Cos(a), 0.5 + 0.5 * Math.Cos(a + 2.1), 0.5 + 0.5 * Math.Cos(a + 4.2) });
  root.InsertChild(s, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(4.0 * Math.Sin(a), 0.2, 4.0 * Math.Cos(a)));
}

// Infinite plane with checker.
Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.2, 0.2, 0.2 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(1.0, 1.0, new double[] { 0.9, 0.9, 0.9 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

/// <summary>
/// 360 x 180 degree panorama: x maps to the longitude (-180 .. 180 degrees, 0 = looking along +z),
/// y to the latitude (+90 at the top row .. -90 at the bottom row).
/// </summary>
class EquirectangularCamera : ICamera
{
  Vector3d center;

  public EquirectangularCamera(Vector3d center)
  {
    this.center = center;
  }

  public double Width { get; set; } = 720;

  public double Height { get; set; } = 360;

  public double AspectRatio
  {
    get => Width / Height;
    set => Height = Width / value;
  }

  public bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1)
  {
    double lon = (x / Width - 0.5) * 2.0 * Math.PI;
    double lat = (0.5 - y / Height) * Math.PI;
    p0 = center;
    p1 = new Vector3d(Math.Cos(lat) * Math.Sin(lon), Math.Sin(lat), Math.Cos(lat) * Math.Cos(lon));
    return true;
  }
}
