using Globes;

// The two balls of StudentSphereScene.cs made of a module's solid (--module modules/Globes).
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.4, 24));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };
scene.Camera = new StaticCamera(new Vector3d(0.4, 0.8, -6.0), new Vector3d(0.0, -0.1, 1.0), 45.0);
scene.Sources = new LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.6));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 5.0, -4.0), 1.2));

TangentGlobe s = new TangentGlobe();
s.SetAttribute(PropertyName.COLOR, new double[] { 1.0, 0.6, 0.1 });
root.InsertChild(s, Matrix4d.Scale(1.6, 0.7, 1.1) * Matrix4d.RotateZ(0.5) * Matrix4d.CreateTranslation(0.3, 0.2, 0.5));
s = new TangentGlobe();
s.SetAttribute(PropertyName.COLOR, new double[] { 0.2, 0.5, 1.0 });
root.InsertChild(s, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(-1.8, -0.4, -0.8));

Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.7, 0.7, 0.7 });
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.2, 0.0));
