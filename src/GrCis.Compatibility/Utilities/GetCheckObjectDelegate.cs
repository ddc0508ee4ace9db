namespace Utilities;

/// <summary>Finds (or checks) the object an id stands for (GrCis); default(T) when there is none.</summary>
public delegate T GetCheckObjectDelegate<T>(string id);
