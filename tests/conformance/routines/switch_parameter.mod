MODULE switch_parameter
  ! Tests: a switch parameter carries only presence: \Loud given or not,
  ! seen through Present.
  PROC say(string text \switch Loud)
    IF Present(Loud) THEN
      TPWrite text + "!";
    ELSE
      TPWrite text;
    ENDIF
  ENDPROC
  PROC main()
    say "hi";
    say "hi" \Loud;
  ENDPROC
ENDMODULE
