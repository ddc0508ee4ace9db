//////////////////////////////////////////////////
// Hedgehog in the cage (by M. Wirth 2012): CSG of stretched spheres
// (the same as the built-in "Hedgehog in the cage").

Debug.Assert(scene != null);
Debug.Assert(context != null);

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.2, 0.6, 0.2, 16));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.05 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 2.0, -7.0),
                                new Vector3d(0.0, -0.32, 1.0),
                                40.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-8.0, 5.0, -3.0), 1.0));

// --- NODE DEFINITIONS ----------------------------------------------------

// Cage.
CSGInnerNode cage = new CSGInnerNode(SetOperation.Difference);
cage.SetAttribute(PropertyName.COLOR, new double[] { 0.70, 0.93, 0.20 });

CSGInnerNode cylinder1 = Intersect(Matrix4d.Scale(1.0, 1000.0, 1.0), Matrix4d.Scale(1000.0, 1.5, 1000.0));
cage.InsertChild(cylinder1, Matrix4d.Identity);

CSGInnerNode cylinder2 = Intersect(Matrix4d.Scale(1.0, 1000.0, 1.0), Matrix4d.Scale(1000.0, 1.5, 1000.0));
cage.InsertChild(cylinder2, Matrix4d.Scale(0.9));

Sphere holeUpDown = new Sphere();
cage.InsertChild(holeUpDown, Matrix4d.Scale(0.5, 1000.0, 0.5));

CSGInnerNode hole1 = Intersect(Matrix4d.Scale(1000.0, 1.1, 1000.0), Matrix4d.Scale(0.4, 1000.0, 1000.0));
cage.InsertChild(hole1, Matrix4d.Identity);

CSGInnerNode hole2 = Intersect(Matrix4d.Scale(1000.0, 1.1, 1000.0), Matrix4d.Scale(0.4, 1000.0, 1000.0));
cage.InsertChild(hole2, Matrix4d.RotateY(Math.PI / 3));

CSGInnerNode hole3 = Intersect(Matrix4d.Scale(1000.0, 1.1, 1000.0), Matrix4d.Scale(0.4, 1000.0, 1000.0));
cage.InsertChild(hole3, Matrix4d.RotateY(Math.PI / -3));

// Hedgehog.
CSGInnerNode hedgehog = new CSGInnerNode(SetOperation.Union);
hedgehog.SetAttribute(PropertyName.COLOR, new double[] { 0.4, 0.05, 0.05 });

Sphere body = new Sphere();
hedgehog.InsertChild(body, Matrix4d.Scale(0.48));

Matrix4d needle = Matrix4d.Scale(0.06, 1000.0, 0.06);
hedgehog.InsertChild(Intersect(needle, Matrix4d.Scale(1.2)), Matrix4d.Identity);
hedgehog.InsertChild(Intersect(needle, Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0.0, 0.1, 0.0)),
                     Matrix4d.RotateX(Math.PI / -3));
hedgehog.InsertChild(Intersect(needle, Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0.0, -0.25, 0.0)),
                     Matrix4d.RotateX(Math.PI / -3) * Matrix4d.RotateY(Math.PI * -0.4));
hedgehog.InsertChild(Intersect(needle, Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0.0, 0.2, 0.0)),
                     Matrix4d.RotateX(Math.PI / -3) * Matrix4d.RotateY(Math.PI * -0.8));
hedgehog.InsertChild(Intersect(needle, Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0.0, -0.2, 0.0)),
                     Matrix4d.RotateX(Math.PI / -3) * Matrix4d.RotateY(Math.PI * 0.4));
hedgehog.InsertChild(Intersect(needle, Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0.0, -0.25, 0.0)),
                     Matrix4d.RotateX(Math.PI / -3) * Matrix4d.RotateY(Math.PI * 0.8));

// All together.
CSGInnerNode all = new CSGInnerNode(SetOperation.Union);
all.InsertChild(cage, Matrix4d.RotateY(0.25));
all.InsertChild(hedgehog, Matrix4d.Rotate(new Vector3d(0.0, 1.0, 1.0), 0.1) * Matrix4d.CreateTranslation(0.0, -0.1, 0.0));
root.InsertChild(all, Matrix4d.RotateZ(0.1));

// Intersection of two differently stretched unit spheres.
CSGInnerNode Intersect(Matrix4d first, Matrix4d second)
{
  CSGInnerNode node = new CSGInnerNode(SetOperation.Intersection);
  node.InsertChild(new Sphere(), first);
  node.InsertChild(new Sphere(), second);
  return node;
}
