//////////////////////////////////////////////////
// A scene in the classic GrCis style: helper method, classes declared
// between statements and used before their declaration, OpenTK 3 calls.

Debug.Assert(scene != null);
Debug.Assert(context != null);

// Root node with a shared reflectance model and material.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.8, 0.2, 16));
scene.Intersectable = root;

scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };

// The camera class is declared further below.
scene.Camera = new FisheyeCamera(new Vector3d(0.0, 0.0, -5.0), 180.0);

// Lights: a fully qualified generic collection.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new ConstantLight(0.8));

// Nodes built by a method declared in the script.
for (int i = 0; i < 3; i++)
  root.InsertChild(MakeNode(i), Matrix4d.Scale(0.5) * Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(i * 2.0, 0.0, 0.0));

// Texture declared further below, applied to the last child.
DefaultSceneNode last = null;
foreach (ISceneNode n in root.Children)
  last = (DefaultSceneNode)n;
last.SetAttribute(PropertyName.TEXTURE, new HashStripes(4));

// Fully qualified hash from the library.
long hash = (long)MathSupport.RandomStatic.numericRecipes((ulong)12345);
context["hash"] = hash;

ISceneNode MakeNode(int index)
{
  DefaultSceneNode node = new DefaultSceneNode();
  node.SetAttribute(PropertyName.COLOR, new double[] { 0.1 * index, 0.5, 1.0 - 0.1 * index });
  return node;
}

/// <summary>Equidistant fisheye: the angle from the axis grows linearly with the distance from the image centre.</summary>
class FisheyeCamera : ICamera
{
  public double AspectRatio { get; set; } = 1.0;
  public double Width { get; set; } = 400;
  public double Height { get; set; } = 400;

  Vector3d center;
  double maxAngle;

  public FisheyeCamera(Vector3d center, double fovDeg)
  {
    this.center = center;
    maxAngle = MathHelper.DegreesToRadians(fovDeg) * 0.5;
  }

  public bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1)
  {
    p0 = center;
    double u = (2.0 * x / Width) - 1.0;
    double v = 1.0 - (2.0 * y / Height);
    double r = Math.Sqrt(u * u + v * v);
    if (r > 1.0)
    {
      p1 = Vector3d.Zero;
      return false;
    }
    double theta = r * maxAngle;
    double phi = Math.Atan2(v, u);
    p1 = new Vector3d(Math.Sin(theta) * Math.Cos(phi), Math.Sin(theta) * Math.Sin(phi), Math.Cos(theta));
    return true;
  }
}

class ConstantLight : ILightSource
{
  public Vector3d? position { get; set; }
  double intensity;

  public ConstantLight(double intensity) => this.intensity = intensity;

  public double[] GetIntensity(Intersection intersection, out Vector3d dir)
  {
    dir = Vector3d.Zero;
    return new double[] { intensity, intensity, intensity };
  }
}

class HashStripes : ITexture
{
  int count;

  public HashStripes(int count) => this.count = count;

  public long Apply(Intersection inter)
  {
    int stripe = (int)Math.Floor(inter.TextureCoord.X * count);
    if ((stripe & 1) == 1)
      inter.SurfaceColor = new double[] { 1.0, 1.0, 1.0 };
    return (long)MathSupport.RandomStatic.numericRecipes((ulong)stripe);
  }
}
