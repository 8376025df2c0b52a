MODULE SocketSubMessages
    ! A PC sends one message of several sub-messages (the pattern of pac48's ROS driver,
    ! ROS_receive_msg_all_data): a 4-byte type, then each sub-message's fields followed by
    ! the next type, read at an index that each sub-message moves on by its length; a type
    ! of 0 ends the message.  A joint sub-message is 8 bytes, a force one 4.  The messages
    ! tried are each type both as the header alone (the force's UnpackRawBytes then fails:
    ! ERR_OUTOFBND, a real message too short) and followed by enough bytes 0 for three
    ! sub-messages; two sub-messages in a row (joint then force) are probes, and reach
    ! "both := 1".
    VAR socketdev server;
    VAR socketdev client;
    VAR rawbytes buffer;
    VAR num msg_type := 0;
    VAR num joint := -1;
    VAR num force := -1;
    VAR num got_joint := 0;
    VAR num got_force := 0;
    VAR num both := 0;

    PROC ReadAll()
        VAR num i := 5;
        got_joint := 0;
        got_force := 0;
        SocketReceive client \RawData:=buffer \Time:=WAIT_MAX;
        UnpackRawBytes buffer, 1, msg_type \IntX:=DINT;
        WHILE msg_type <> 0 DO
            IF msg_type = 1 THEN
                UnpackRawBytes buffer, i + 0, joint \IntX:=DINT;
                got_joint := 1;
                i := i + 8;
            ELSEIF msg_type = 2 THEN
                UnpackRawBytes buffer, i, force \IntX:=DINT;
                got_force := 1;
                i := i + 4;
            ELSE
                RETURN;
            ENDIF
            UnpackRawBytes buffer, i, msg_type \IntX:=DINT;
        ENDWHILE
    ENDPROC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 11000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            ReadAll;
            IF got_joint = 1 AND got_force = 1 THEN
                both := 1;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
