MODULE Watch
  ! Another task reads the position the motion task stored.
  PERS robtarget pLast := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR num tab{2} := [1, 2];
  VAR num i := 1;
  PROC main()
    WHILE TRUE DO
      IF pLast.trans.z > 650 i := 3;
      tab{i} := 0;
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
