using System;
using System.Collections.Generic;

namespace GrCis.Scripting.Compilation;

/// <summary>A small least-recently-used map; evicted values are handed to a callback. Not thread-safe.</summary>
internal sealed class LruCache<TKey, TValue> where TKey : notnull
{
  readonly int capacity;
  readonly Action<TValue> evicted;
  readonly Dictionary<TKey, LinkedListNode<(TKey Key, TValue Value)>> map = new();
  readonly LinkedList<(TKey Key, TValue Value)> order = new();

  public LruCache(int capacity, Action<TValue> evicted)
  {
    if (capacity < 1)
      throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "The cache must hold at least one entry.");
    this.capacity = capacity;
    this.evicted = evicted;
  }

  public int Count => map.Count;

  public bool TryGet(TKey key, out TValue value)
  {
    if (map.TryGetValue(key, out var node))
    {
      order.Remove(node);
      order.AddFirst(node);
      value = node.Value.Value;
      return true;
    }
    value = default!;
    return false;
  }

  public void Add(TKey key, TValue value)
  {
    Remove(key);
    map[key] = order.AddFirst((key, value));
    while (map.Count > capacity)
    {
      var last = order.Last!;
      order.RemoveLast();
      map.Remove(last.Value.Key);
      evicted(last.Value.Value);
    }
  }

  public bool Remove(TKey key)
  {
    if (!map.Remove(key, out var node))
      return false;
    order.Remove(node);
    return true;
  }

  public void Clear()
  {
    foreach (var (_, value) in order)
      evicted(value);
    order.Clear();
    map.Clear();
  }
}
