// Decodes every event of an LCM log file with the Java types lcm-gen made from lcmtypes/dvpr
// (dvpr_lcmtypes.jar), read with LCM's own Java log reader (lcm.logging.Log of Debian's lcm.jar).
// Each event must carry the fingerprint of exactly one dvpr type, decode, and encode back to the
// same bytes (LCM's own LCM_SELF_TEST messages, which lcm-logger records, are skipped). With --live, every message's utime must lie within a second of the instant
// lcm-logger received it (the event's timestamp, wall clock): dvpr stamps utime in microseconds
// since the Unix epoch.
//
//   java -cp /usr/share/java/lcm.jar:dvpr_lcmtypes.jar tests/tools/lcm_types/DecodeDvprLog.java \
//        dvpr_lcmtypes.jar LOG [--live]
//
// Prints "java: N events decoded (type: count, ...)" and exits 0, or names the first bad event
// and exits 1.
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.util.Enumeration;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

public class DecodeDvprLog {
  // Every class of package dvpr in the jar, by its fingerprint.
  static Map<Long, Class<?>> TypesOf(String jar) throws Exception {
    Map<Long, Class<?>> types = new HashMap<>();
    try (JarFile file = new JarFile(jar)) {
      for (Enumeration<JarEntry> e = file.entries(); e.hasMoreElements();) {
        String name = e.nextElement().getName();
        if (!name.startsWith("dvpr/") || !name.endsWith(".class") || name.contains("$")) continue;
        Class<?> c = Class.forName(name.replace('/', '.').replace(".class", ""));
        types.put(c.getField("LCM_FINGERPRINT").getLong(null), c);
      }
    }
    return types;
  }

  static long Fingerprint(byte[] data) {
    long v = 0;
    for (int i = 0; i < 8 && i < data.length; ++i) v = (v << 8) | (data[i] & 0xff);
    return v;
  }

  static final int kTrailer = 34;  // robot, instance, counter and a 16-byte tag (docs/security.md)

  public static void main(String[] args) throws Exception {
    Map<Long, Class<?>> types = TypesOf(args[0]);
    boolean live = args.length > 2 && args[2].equals("--live");
    lcm.logging.Log log = new lcm.logging.Log(args[1], "r");
    Map<String, Integer> counts = new TreeMap<>();
    long events = 0;
    for (;;) {
      lcm.logging.Log.Event ev;
      try {
        ev = log.readNext();
      } catch (EOFException end) {
        break;
      }
      if (ev.channel.equals("LCM_SELF_TEST")) continue;  // LCM's own, sent when a udpm instance opens
      String where = "event " + ev.eventNumber + " on " + ev.channel;
      if (live) {
        // A launched team's message ends in its 34-byte authentication trailer
        // (agents/auth/message_auth.h): the LCM message is what precedes it.
        if (ev.data.length < 8 + kTrailer) Fail(where + ": shorter than a message and its trailer");
        ev.data = java.util.Arrays.copyOf(ev.data, ev.data.length - kTrailer);
      }
      Class<?> type = ev.data.length >= 8 ? types.get(Fingerprint(ev.data)) : null;
      if (type == null) Fail(where + ": no dvpr type has its fingerprint");
      Object msg = type.getConstructor(byte[].class).newInstance((Object) ev.data);
      ByteArrayOutputStream bytes = new ByteArrayOutputStream();
      type.getMethod("encode", java.io.DataOutput.class).invoke(msg, new DataOutputStream(bytes));
      if (!java.util.Arrays.equals(bytes.toByteArray(), ev.data)) Fail(where + ": does not encode back to its bytes");
      long utime = type.getField("utime").getLong(msg);
      if (live && Math.abs(utime - ev.utime) > 1000000) {
        Fail(where + ": utime " + utime + " is " + (utime - ev.utime) + " us from the wall clock at receipt");
      }
      counts.merge(type.getSimpleName(), 1, Integer::sum);
      ++events;
    }
    if (events == 0) Fail("no events in " + args[1]);
    System.out.println("java: " + events + " events decoded " + counts);
  }

  static void Fail(String why) {
    System.err.println("java: " + why);
    System.exit(1);
  }
}
