MODULE prog
  ! Setup runs the same way every time: its steps are told by what they leave behind
  VAR socketdev server;
  VAR num limits{3} := [0, 0, 0];
  VAR num divisor := 1;

  PROC Setup()
    IF SocketGetStatus(server) = SOCKET_CLOSED SocketCreate server;
    limits{1} := 10;
    limits{2} := 20;
    divisor := 0;
  ENDPROC

  PROC main()
    Setup;
    limits{3} := limits{1} / divisor;
  ENDPROC
ENDMODULE
