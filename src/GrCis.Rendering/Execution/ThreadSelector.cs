namespace Rendering;

/// <summary>GrCis's choice of whether the calling thread takes work unit <paramref name="unit"/>.</summary>
public delegate bool ThreadSelector(long unit);
