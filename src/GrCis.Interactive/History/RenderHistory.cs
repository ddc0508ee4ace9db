using System;
using System.Collections.Generic;

namespace GrCis.Interactive;

/// <summary>
/// The last few renders with back/forward (the demo's « and » buttons). A new render is appended
/// and becomes current; the oldest falls out beyond <see cref="Capacity"/>.
/// </summary>
public sealed class RenderHistory
{
  public const int DefaultCapacity = 5;

  readonly List<RenderRecord> items = new();

  public RenderHistory(int capacity = DefaultCapacity)
  {
    if (capacity < 1)
      throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "History must hold at least one render.");
    Capacity = capacity;
  }

  public int Capacity { get; }

  /// <summary>Oldest first.</summary>
  public IReadOnlyList<RenderRecord> Items => items;

  /// <summary>Index of the current record; −1 when empty.</summary>
  public int Position { get; private set; } = -1;

  public RenderRecord? Current => Position >= 0 ? items[Position] : null;

  public bool CanGoBack => Position > 0;

  public bool CanGoForward => Position >= 0 && Position < items.Count - 1;

  public event EventHandler? Changed;

  public void Add(RenderRecord record)
  {
    ArgumentNullException.ThrowIfNull(record);
    items.Add(record);
    if (items.Count > Capacity)
      items.RemoveAt(0);
    Position = items.Count - 1;
    Changed?.Invoke(this, EventArgs.Empty);
  }

  /// <summary>Steps to the previous render; returns it, or null when already at the oldest.</summary>
  public RenderRecord? Back() => Move(-1);

  public RenderRecord? Forward() => Move(+1);

  RenderRecord? Move(int step)
  {
    int p = Position + step;
    if (Position < 0 || p < 0 || p >= items.Count)
      return null;
    Position = p;
    Changed?.Invoke(this, EventArgs.Empty);
    return items[p];
  }

  /// <summary>Saves the current render as PNG (atomically).</summary>
  public void SaveCurrent(string path) =>
    (Current ?? throw new InvalidOperationException("There is no render to save yet.")).SavePng(path);
}
