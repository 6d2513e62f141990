# NUL bytes in dict strings and paths: is the whole message kept?
import sinsim
for f in [lambda: sinsim.Model({'gyro': {'all': [{'type': 'white\x00x', 'density': '1 deg/sqrt(h)'}]}}), lambda: sinsim.Model('scen\x00arios/x.yaml'), lambda: sinsim.load_record('a\x00b.csv')]:
    try: f(); print("accepted")
    except Exception as e: print(type(e).__name__, repr(str(e)), getattr(e, "diagnostics", None))
