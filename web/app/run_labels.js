// What tells runs apart, in one place for every page: the run's name as the CLI's run labels
// (clients/slipfront_client/results.py run_label: method, what is below the interface, the
// friction law by its scale parameter, n_d).
import { lowerWaveSpeeds, waveSpeeds } from './job_figures.js';

// What is below the interface when it is not the rigid plane (as the CLI's run labels):
// 'bimaterial' for two different elastic solids, 'full space' for two identical ones.
export function belowText(spec) {
  const lower = lowerWaveSpeeds(spec), upper = waveSpeeds(spec);
  if (!lower) return '';
  const same = upper && lower.cs === upper.cs && lower.cp === upper.cp && (spec.lower.density ?? 1) === (spec.material?.density ?? 1);
  return same ? 'full space' : 'bimaterial';
}
