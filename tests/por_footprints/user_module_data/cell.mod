MODULE Cell
  ! reg1 is data of the USER module, of which every task has its own: the partner's
  ! reg1 is another data object, so this task's reads and writes of reg1 are local.
  VAR bool flag := FALSE;
  PROC main()
    reg1 := 1;                           ! LOCAL
    IF reg1 = 2 THEN                     ! LOCAL
      flag := TRUE;                      ! VISIBLE
    ENDIF
  ENDPROC                                ! LOCAL
ENDMODULE
