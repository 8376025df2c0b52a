MODULE recursion_mutual_procedures
  ! Tests: procedures may call each other recursively (countdown split over
  ! two procedures), with output order following the call order.
  PROC ping(num n)
    TPWrite "ping " \Num:=n;
    IF n > 0 pong n - 1;
  ENDPROC
  PROC pong(num n)
    TPWrite "pong " \Num:=n;
    IF n > 0 ping n - 1;
  ENDPROC
  PROC main()
    ping 3;
  ENDPROC
ENDMODULE
