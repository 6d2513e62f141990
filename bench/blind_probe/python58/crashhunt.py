# odd Python objects into every entry point, each in a fresh interpreter; flags signals (segfault/abort) and non-sinsim exceptions
import subprocess, os
os.chdir("/tmp/probe_58")
PRE = "import sinsim, numpy as np, warnings; warnings.simplefilter('ignore'); M='scenarios/grade-tactical.yaml'; SC='scenarios/static.yaml'\n"
cases = {
 "dict_int_keys": "sinsim.Model({1: 2})",
 "dict_none_value": "sinsim.Model({'gyro': None})",
 "dict_bytes_value": "sinsim.Model({'gyro': {'all': [{'type': b'white', 'density': b'0.3 deg/sqrt(h)'}]}})",
 "dict_float_nan": "sinsim.Model({'gyro': {'all': [{'type': 'white', 'density': float('nan')}]}})",
 "dict_bool": "sinsim.Model({'gyro': {'all': [{'type': 'white', 'density': True}]}})",
 "dict_tuple_list": "print(sinsim.Model({'gyro': {'triad': ({'type': 'scale_factor', 'diagonal': ('1 ppm', '2 ppm', '3 ppm')},)}}).yaml())",
 "dict_numpy_float": "sinsim.Model({'gyro': {'all': [{'type': 'white', 'density': np.float64(0.3)}]}})",
 "dict_set": "sinsim.Model({'gyro': {'all': [{'type', 'white'}]}})",
 "dict_huge_list": "sinsim.Model({'gyro': {'x': [{'type': 'ar', 'a': [0.0]*100000, 'sigma': '1 deg/s', 'rate': '1 kHz'}]}})",
 "dict_many_effects": "sinsim.Model({'gyro': {'all': [{'type': 'white', 'density': '1 deg/sqrt(h)'}]*2000}})",
 "dict_long_string": "sinsim.Model({'gyro': {'all': [{'type': 'white', 'density': '1'*10**7 + ' deg/sqrt(h)'}]}})",
 "dict_nul_string": "sinsim.Model({'gyro': {'all': [{'type': 'white\\x00', 'density': '1 deg/sqrt(h)'}]}})",
 "dict_surrogate": "sinsim.Model({'gyro': {'all': [{'type': '\\udcff', 'density': '1 deg/sqrt(h)'}]}})",
 "path_nul": "sinsim.Model('scen\\x00arios')",
 "path_bytes": "sinsim.Model(b'scenarios/grade-tactical.yaml')",
 "path_pathlib": "import pathlib; print(sinsim.Model(pathlib.Path(M)))",
 "path_huge": "sinsim.Model('a'*100000)",
 "scen_dict_none": "sinsim.Scenario({'name': None})",
 "rec_rate_numpy": "a=sinsim.analyze({'rate': np.float32(100), 'gx': np.random.randn(1000)}); print('ok')",
 "rec_rate_bool": "sinsim.analyze({'rate': True, 'gx': np.random.randn(1000)})",
 "rec_rate_nan": "sinsim.analyze({'rate': float('nan'), 'gx': np.random.randn(1000)})",
 "rec_rate_inf": "sinsim.analyze({'rate': float('inf'), 'gx': np.random.randn(1000)})",
 "rec_t_nonmono": "sinsim.analyze({'t': np.random.rand(1000), 'gx': np.random.randn(1000)})",
 "rec_t_const": "sinsim.analyze({'t': np.zeros(1000), 'gx': np.random.randn(1000)})",
 "rec_t_and_rate_conflict": "a=sinsim.analyze({'t': np.arange(1000)/100.0, 'rate': 10, 'gx': np.random.randn(1000)}); print('accepted; first tau', a['gx']['allan']['tau'][0])",
 "rec_complex": "sinsim.analyze({'rate': 100, 'gx': np.random.randn(1000)+1j})",
 "rec_masked": "x=np.ma.masked_array(np.random.randn(1000), mask=[0]*999+[1]); a=sinsim.analyze({'rate': 100, 'gx': x}); print('accepted masked')",
 "rec_big_endian": "x=np.random.randn(1000); a=sinsim.analyze({'rate': 100, 'gx': x.astype('>f8')}); b=sinsim.analyze({'rate':100,'gx':x}); print(np.array_equal(a['gx']['allan']['adev'], b['gx']['allan']['adev']))",
 "rec_readonly": "x=np.random.randn(1000); x.flags.writeable=False; sinsim.analyze({'rate': 100, 'gx': x}); print('ok')",
 "rec_huge_len": "x=np.broadcast_to(np.float64(1.0), (400_000_000,)); sinsim.analyze({'rate': 100, 'gx': x})",
 "rec_source_int": "sinsim.analyze({'rate': 100, 'source': 5, 'gx': np.random.randn(1000)})",
 "fit_dict_temp_only": "sinsim.fit({'rate': 100, 'temp': np.random.randn(1000)+300})",
 "diag_model_none_str": "sinsim.diagnose({'rate': 100, 'gx': np.random.randn(5000)*1e-3}, 'none', realisations=8)",
 "mc_models_generator": "b=sinsim.mc(SC, models=(m for m in [M]), runs=1); print(b['labels'])",
 "run_scenario_model_obj_swap": "sinsim.run(sinsim.Model(M))",
 "mc_model_dict_bad_label": "sinsim.mc(SC, models=[{'gyro': {}}, {'gyro': {}}], runs=1)",
 "model_pickle": "import pickle; pickle.dumps(sinsim.Model(M))",
 "model_copy": "import copy; m=copy.deepcopy(sinsim.Model(M)); print(m == sinsim.Model(M))",
 "model_hash": "print(hash(sinsim.Model(M)))",
 "subclass_dict": "class D(dict): pass\nprint(sinsim.Model(D({'gyro': {}})))",
 "model_effects_mutation": "m=sinsim.Model(M); e=m.effects(); e[0]['params']['sigma']=1e9; print(m.get('gyro','all',0,'sigma'))",
}
for name, code in cases.items():
    try:
        p = subprocess.run(["/usr/bin/python3", "-c", PRE + code], capture_output=True, text=True, timeout=60, env={**os.environ, "PYTHONPATH": "/tmp/probe_bin58/py"})
        err = p.stderr.strip().splitlines(); last = err[-1] if err else ""
        tag = "CRASH(signal %d)" % -p.returncode if p.returncode < 0 else ("ok" if p.returncode == 0 else "exc")
        print(f"[{name}] {tag}: {(p.stdout.strip()[-150:] + ' | ' + last)[:260]}")
    except subprocess.TimeoutExpired: print(f"[{name}] TIMEOUT")
