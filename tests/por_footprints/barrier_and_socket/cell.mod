MODULE Cell
  ! With a barrier in the program, the last ENDPROC of a task is shared: ending the
  ! task decides whether a partner waiting at the barrier waits forever.
  VAR syncident ready;
  PERS tasks both{2} := [["main task"], ["task 2 (partner)"]];
  VAR socketdev client;
  VAR string reply := "";
  VAR num count := 0;
  PROC main()
    count := count + 1;                  ! LOCAL
    Prepare;                             ! LOCAL
    WaitSyncTask ready, both;            ! SHARED
    SocketCreate client;                 ! LOCAL
    SocketReceive client \Str:=reply;    ! LOCAL
    count := StrLen(reply);              ! LOCAL
  ENDPROC                                ! SHARED
  PROC Prepare()
    count := count * 2;                  ! LOCAL
  ENDPROC                                ! LOCAL
ENDMODULE
