using SomeAuthor;

// A scene using a third-party module: its solid and its texture.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
scene.Intersectable = root;

Slab slab = new Slab(0.5);
slab.SetAttribute(PropertyName.TEXTURE, new RingsTexture(2.0, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(slab, Matrix4d.CreateTranslation(0.0, 0.0, 3.0));
