MODULE Cell
  ! The partner writes note only in its ERROR handler: still a write of note by
  ! another task, so the condition on note depends on the partner's steps.
  PERS num note := 0;
  VAR bool reset := FALSE;
  PROC main()
    FOR i FROM 1 TO 2 DO                 ! LOCAL
      IF note > 1 THEN                   ! SHARED
        reset := TRUE;                   ! VISIBLE
      ENDIF
    ENDFOR
    note := 0;                           ! SHARED
  ENDPROC                                ! LOCAL
ENDMODULE
