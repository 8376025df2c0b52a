MODULE JobMain
  ! Tests: stubs for a job dispatcher whose job table module was not given: a CONST
  ! that sizes an array (declared CONST, at least 1), a TEST subject, a record read by
  ! component, a function in a condition, a procedure called with a loop variable.
  VAR num nDone{nMaxJobs};

  PROC main()
    FOR i FROM 1 TO nMaxJobs DO
      TEST nJobType{i}
      CASE 1:
        RunJob i;
      DEFAULT:
        IF JobAllowed(i) THEN
          nDone{i} := nDone{i} + 1;
        ENDIF
      ENDTEST
    ENDFOR
    IF pLast.trans.z > nSafeZ THEN
      TPWrite "above the safe height";
    ENDIF
  ENDPROC
ENDMODULE
