//////////////////////////////////////////////////
// A CheckerTexture subclass declared after its use, on a sphere.

CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
scene.Intersectable = root;
scene.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -5.0), new Vector3d(0.0, 0.0, 1.0), 40.0);
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(1.0));

Sphere s = new Sphere();
s.SetAttribute(PropertyName.COLOR, new double[] { 0.2, 0.2, 0.8 });
s.SetAttribute(PropertyName.TEXTURE, new Stripes(10.0, new double[] { 1.0, 1.0, 0.0 }));
root.InsertChild(s, Matrix4d.Identity);

/// <summary>Only the u direction alternates: vertical stripes.</summary>
class Stripes : CheckerTexture
{
  public Stripes(double fu, double[] color2) : base(fu, 1.0, color2) { }

  public override long Apply(Intersection inter)
  {
    long u = (long)Math.Floor(inter.TextureCoord.X * Fu);
    if ((u & 1L) != 0L)
      inter.SurfaceColor = Util.ColorClone(Color2);
    return (long)MathSupport.RandomStatic.numericRecipes((ulong)u);
  }
}
