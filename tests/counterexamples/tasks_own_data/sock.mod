MODULE Sock(SYSMODULE)
    ! A set-up routine both tasks load, as the ROS drivers' ROS_socket.sys is.
    PROC init_socket(VAR socketdev server_socket, num port)
        IF (SocketGetStatus(server_socket) = SOCKET_CLOSED) SocketCreate server_socket;
        IF (SocketGetStatus(server_socket) = SOCKET_CREATED) SocketBind server_socket, "127.0.0.1", port;
        IF (SocketGetStatus(server_socket) = SOCKET_BOUND) SocketListen server_socket;
    ENDPROC
ENDMODULE
