MODULE Prog
  ! An IF Present(p) branch of a procedure that every call leaves p out of never runs,
  ! whatever a client sends: the ROS motion server calls ROS_receive_msg_joint_traj_pt
  ! without \wait_time, so its branch for one is "never reached under any input".  Send
  ! is called with \Urgent once, behind a message no tried message parses to (7/3): its
  ! Present branch keeps resting on the messages tried.
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num value := 0;
  VAR num served := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    WHILE TRUE DO
      Receive;
      IF StrToVal(command, value) THEN
        IF value * 3 = 7 Send \Urgent;
      ENDIF
      Send;
    ENDWHILE
  ENDPROC
  PROC Receive(\num wait_time)
    IF Present(wait_time) THEN
      SocketReceive client \Str:=command \Time:=wait_time;
    ELSE
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
    ENDIF
  ENDPROC
  PROC Send(\switch Urgent)
    IF Present(Urgent) THEN
      served := served + 2;
    ENDIF
    served := served + 1;
    IF served > 100 served := 0;
  ENDPROC
ENDMODULE
