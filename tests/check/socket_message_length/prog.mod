MODULE SocketMessageLength
    ! A client logs each message; one longer than 12 characters is kept whole, a shorter
    ! one with a suffix (a pattern of the Hanoi socket task, there with 72).  The length
    ! is compared after the message was copied: a message of 13 characters takes the
    ! first branch.
    VAR socketdev client;
    VAR string received := "";
    VAR string kept := "";
    VAR num size := 0;
    VAR num long := 0;

    PROC main()
        SocketCreate client;
        SocketConnect client, "10.0.0.2", 5000 \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=received \Time:=WAIT_MAX;
            kept := received;
            size := StrLen(kept);
            IF size > 12 THEN
                long := 1;
            ELSE
                long := 0;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
