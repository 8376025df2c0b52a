MODULE conditional_argument
  ! Tests: a conditional argument \Speed?Speed passes the caller's optional
  ! parameter on only if it is present; an absent one stays absent.
  PROC inner(\num Speed)
    IF Present(Speed) THEN
      TPWrite "speed " \Num:=Speed;
    ELSE
      TPWrite "default speed";
    ENDIF
  ENDPROC
  PROC outer(\num Speed)
    inner \Speed?Speed;
  ENDPROC
  PROC main()
    outer \Speed:=7;
    outer;
  ENDPROC
ENDMODULE
