MODULE LocalRecordSocket
    ! Routine data of a record type shows its components by name (.head.msg_type), and a
    ! socket shows its state as SocketGetStatus names it (<socketdev: created>).
    RECORD header
        num msg_type;
        num length;
    ENDRECORD
    RECORD message
        header head;
        string body;
    ENDRECORD

    PROC main()
        VAR message raw_message;
        VAR socketdev welcome_socket{2};
        VAR num per_byte := 0;
        raw_message.head.msg_type := 3;
        SocketCreate welcome_socket{1};
        per_byte := 100 / raw_message.head.length;
    ENDPROC
ENDMODULE
