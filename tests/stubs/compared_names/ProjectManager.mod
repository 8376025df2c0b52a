MODULE ProjectManager
  ! Issue 28 (survey: a palletizing cell's PickMaster project manager): a status and its
  ! codes, names of a module not given, compared only with each other. Nothing else types
  ! them, so num is assumed (as for a TEST's CASE values) and the codes are told apart.
  ! Before, the names were left undeclared and the written module did not load (RMC201).
  PROC main()
    IF PM_PROJECT_STATUS = PM_PROJECT_STOPPED OR PM_PROJECT_STATUS = PM_PROJECT_ERROR THEN
      TPWrite "project stopped";
    ENDIF
    IF PM_PROJECT_STATUS <> PM_PROJECT_RUNNING THEN
      TPWrite "project not running";
    ENDIF
  ENDPROC
ENDMODULE
