# Python writes over its own inputs where the CLI refuses (docs/limits.md: "A command never writes over a file it read")
import sinsim, shutil, subprocess, warnings
warnings.simplefilter("ignore")
B = "/tmp/probe_bin58/sinsim"
subprocess.run([B, "synth", "scenarios/grade-tactical.yaml", "--rate", "100", "--duration", "20", "-o", "out/ow_rec.csv"], capture_output=True)
sinsim.analyze("out/ow_rec.csv", json="out/ow_rec.csv")
print("analyze(json=record): record now starts with", repr(open("out/ow_rec.csv").read(20)))
shutil.copy("scenarios/grade-tactical.yaml", "out/ow_model.yaml")
sinsim.synth("out/ow_model.yaml", 100, 1, "out/ow_model.yaml")
print("synth(model, path=model): model now starts with", repr(open("out/ow_model.yaml").read(20)))
shutil.copy("scenarios/grade-tactical.yaml", "out/ow_model2.yaml")
p = subprocess.run([B, "synth", "out/ow_model2.yaml", "--rate", "100", "--duration", "1", "-o", "out/ow_model2.yaml"], capture_output=True, text=True)
print("CLI same: rc", p.returncode, p.stderr.strip())
