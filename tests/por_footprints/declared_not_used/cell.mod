MODULE Cell
  ! Both tasks declare every PERS of the cell (as backups load one module of
  ! declarations in each task), but only this task's code names cycles, and only the
  ! partner's names hits: writing either is LOCAL.  Both name done: writing it is SHARED.
  PERS num cycles := 0;
  PERS num hits := 0;
  PERS bool done := FALSE;
  PROC main()
    FOR i FROM 1 TO 3 DO                 ! LOCAL
      cycles := cycles + 1;              ! LOCAL
    ENDFOR
    done := TRUE;                        ! SHARED
  ENDPROC
ENDMODULE
