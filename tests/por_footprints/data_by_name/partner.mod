MODULE Partner
  PERS num note := 0;
  VAR num own := 0;
  PROC main()
    FOR k FROM 1 TO 2 DO                 ! LOCAL
      own := own + 1;                    ! LOCAL
      SetDataVal "note", own;            ! SHARED
    ENDFOR
  ENDPROC                                ! LOCAL
ENDMODULE
