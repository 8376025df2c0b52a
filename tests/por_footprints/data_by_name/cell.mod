MODULE Cell
  ! Data reached by name: GetDataVal and SetDataVal look the name up in their own task,
  ! so the partner's SetDataVal counts as a write of every datum it can name (note).
  PERS num note := 0;
  VAR num mine := 0;
  VAR num copy := 0;
  PROC main()
    FOR i FROM 1 TO 2 DO                 ! LOCAL
      mine := mine + 1;                  ! LOCAL
      IF note > 1 THEN                   ! SHARED
        mine := 0;                       ! LOCAL
      ENDIF
      GetDataVal "mine", copy;           ! SHARED
    ENDFOR
  ENDPROC                                ! LOCAL
ENDMODULE
