# The model-file samples in docs/model-format.md and docs/error-models.md: load, write, reload, fixed point; synth via CLI
import sinsim, re, os, subprocess, filecmp
os.chdir("/tmp/probe_58")
for doc in ["model-format.md", "error-models.md"]:
    txt = open(f"/work/main/docs/{doc}").read()
    y = re.findall(r"```yaml\n(.*?)```", txt, re.S)[0]
    f = f"out/sample_{doc}.yaml"; open(f, "w").write(y)
    m = sinsim.Model(f); m.write(f + ".w1"); m1 = sinsim.Model(f + ".w1"); m1.write(f + ".w2")
    print(doc, m, "| w1==w2 bytes:", filecmp.cmp(f + ".w1", f + ".w2", shallow=False), "| m==m1:", m == m1, "| m1==m2:", m1 == sinsim.Model(f + ".w2"))
    p = subprocess.run(["/tmp/probe_bin58/sinsim", "synth", f, "--rate", "1000", "--duration", "5", "-o", f + ".csv"], capture_output=True, text=True)
    print("   CLI synth rc", p.returncode, p.stderr.strip()[:200])
    print("   " + open(f + ".w1").read().replace("\n", "\n   "))
