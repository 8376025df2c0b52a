MODULE MainModule
    ! Tests: SocketSend \Data takes an array of byte; a num is refused before the program runs.
    VAR socketdev client;
    VAR num single := 1;
    PROC main()
        SocketSend client \Data:=single;
    ENDPROC
ENDMODULE
