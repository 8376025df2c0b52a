MODULE Cell
  ! tool0 is the BASE module's PERS, which every task names without declaring it: the
  ! partner's write of it is a write of the same data object.
  VAR bool flag := FALSE;
  PROC main()
    tool0.tload.mass := 1;               ! SHARED
    IF tool0.tload.mass = 2 THEN         ! SHARED
      flag := TRUE;                      ! VISIBLE
    ENDIF
  ENDPROC                                ! LOCAL
ENDMODULE
