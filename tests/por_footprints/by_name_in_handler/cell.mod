MODULE Cell
  ! The partner writes note by name in its ERROR handler only: still a write of every
  ! datum the partner can name, so reading note here depends on it.
  PERS num note := 0;
  VAR num mine := 0;
  VAR num seen := 0;
  PROC main()
    FOR i FROM 1 TO 2 DO                 ! LOCAL
      mine := mine + 1;                  ! LOCAL
      IF note > 1 THEN                   ! SHARED
        seen := 1;                       ! VISIBLE
      ENDIF
    ENDFOR
  ENDPROC                                ! LOCAL
ENDMODULE
