MODULE WeldJobs
  ! Issue 28: record types of a module not given, declared with values whose parts name
  ! other missing data. The record still has one component per part (it used to collapse
  ! to one num component, which no value of three parts fits). For jobdata, .name, read as
  ! a string, takes the string place, and job2's value tells the type of the first part,
  ! which job1's does not (nWeldSpeed); the missing parts get their places' types. For
  ! clampdata nothing tells the first part's type: num is assumed, for nClampForce too.
  PERS jobdata job1 := [nWeldSpeed, 2, "seam A"];
  PERS jobdata job2 := [15, nPasses, sSchedule];
  PERS clampdata clamp1 := [nClampForce, TRUE];

  PROC main()
    TPWrite job1.name;
    TPWrite job2.name;
  ENDPROC
ENDMODULE
